#include "glint/Cube.hpp"

namespace glint {

Cube::Cube(vec3 position, double size, const Material& material, int object)
    : position_(position), size_(size), material_(material), object_(object) {
  const vec3 p = position;
  const vec3 q = position + vec3(size);
  const vec3 ex(size, 0.0, 0.0);
  const vec3 ey(0.0, size, 0.0);
  const vec3 ez(0.0, 0.0, size);
  // Edge order chosen so that normalize(a x b) points out of the cube.
  faces_ = {Rectangle(p, ez, ey),                     // x = min, normal -x
            Rectangle(vec3(q.x, p.y, p.z), ey, ez),   // x = max, normal +x
            Rectangle(p, ex, ez),                     // y = min, normal -y
            Rectangle(vec3(p.x, q.y, p.z), ez, ex),   // y = max, normal +y
            Rectangle(p, ey, ex),                     // z = min, normal -z
            Rectangle(vec3(p.x, p.y, q.z), ex, ey)};  // z = max, normal +z
}

bool Cube::Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const {
  int best = -1;
  double bestT = tMax;
  for (int i = 0; i < 6; ++i) {
    double t = 0.0;
    if (faces_[i].Intersect(origin, direction, bestT, t)) {
      bestT = t;
      best = i;
    }
  }
  if (best < 0) return false;
  const Rectangle& face = faces_[best];
  hit.t = bestT;
  hit.point = face.PointAt(origin, direction, bestT);
  hit.normal = face.Normal();
  hit.material = &material_;
  hit.object = object_;
  hit.light = false;
  return true;
}

bool Cube::IntersectAny(vec3 origin, vec3 direction, double tMax) const {
  double t = 0.0;
  for (const Rectangle& face : faces_) {
    if (face.Intersect(origin, direction, tMax, t)) return true;
  }
  return false;
}

}  // namespace glint
