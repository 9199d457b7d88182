#include "glint/Wall.hpp"

namespace glint {

Wall::Wall(vec3 position, double size, const std::array<Material, kSides>& materials,
           int firstObject)
    : position_(position), size_(size), materials_(materials), firstObject_(firstObject) {
  const vec3 p = position;
  const vec3 q = position + vec3(size);
  const vec3 ex(size, 0.0, 0.0);
  const vec3 ey(0.0, size, 0.0);
  const vec3 ez(0.0, 0.0, size);
  // Edge order chosen so that normalize(a x b) points into the room.
  faces_[kLeft] = Rectangle(p, ey, ez);                       // x = 0, normal +x
  faces_[kCeiling] = Rectangle(vec3(p.x, q.y, p.z), ex, ez);  // y = 1, normal -y
  faces_[kRight] = Rectangle(vec3(q.x, p.y, p.z), ez, ey);    // x = 1, normal -x
  faces_[kFloor] = Rectangle(p, ez, ex);                      // y = 0, normal +y
  faces_[kBack] = Rectangle(p, ex, ey);                       // z = 0, normal +z
}

bool Wall::Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const {
  int best = -1;
  double bestT = tMax;
  for (int i = 0; i < kSides; ++i) {
    double t = 0.0;
    if (faces_[i].Intersect(origin, direction, bestT, t)) {
      bestT = t;
      best = i;
    }
  }
  if (best < 0) return false;
  hit.t = bestT;
  hit.point = faces_[best].PointAt(origin, direction, bestT);
  hit.normal = faces_[best].Normal();
  hit.material = &materials_[best];
  hit.object = firstObject_ + best;
  hit.light = false;
  return true;
}

bool Wall::Contains(vec3 p, double tolerance) const {
  const vec3 lo = position_ - vec3(tolerance);
  const vec3 hi = position_ + vec3(size_ + tolerance);
  return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
}

}  // namespace glint
