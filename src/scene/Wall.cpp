#include "glint/scene/Wall.hpp"

#include <algorithm>
#include <cmath>

namespace glint {

Wall::Wall(vec3 position, double size, const std::array<Material, kSides>& materials,
           int firstObject)
    : position_(position),
      maxCorner_(position + vec3(size)),
      size_(size),
      materials_(materials),
      firstObject_(firstObject) {
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
  double t = tMax;
  int side = 0;
  if (!Nearer(origin, direction, t, side)) return false;
  FillHit(origin, direction, t, side, hit);
  return true;
}

void Wall::FillHit(vec3 origin, vec3 direction, double t, int side, Hit& hit) const {
  // The side's plane: its axis and whether it is the box's min or max face.
  hit.t = t;
  hit.point = PointOnSlabFace(origin, direction, t, kFaceOfSide[side], position_, maxCorner_);
  hit.normal = faces_[side].Normal();
  hit.material = &materials_[side];
  hit.object = firstObject_ + side;
  hit.light = false;
}

bool Wall::EyeOnAxis(vec3 eye) const {
  const vec3 back = Centre() - vec3(0.0, 0.0, 0.5 * size_);
  const double front = position_.z + size_;
  const double tolerance = 1e-9 * std::max(1.0, size_);
  return std::abs(eye.x - back.x) <= tolerance && std::abs(eye.y - back.y) <= tolerance &&
         eye.z > front;
}

}  // namespace glint
