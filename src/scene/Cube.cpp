#include "glint/scene/Cube.hpp"

namespace glint {

Cube::Cube(vec3 position, double size, const Material& material, int object)
    : position_(position),
      maxCorner_(position + vec3(size)),
      centre_(position + vec3(0.5 * size)),
      // sqrt(3)/2 size, enlarged by a relative 1e-9 so that round-off in the test can
      // never reject a ray that touches a corner.
      boundRadius2_(0.75 * size * size * (1.0 + 1e-9)),
      boundRadius_(std::sqrt(boundRadius2_)),
      size_(size),
      material_(material),
      object_(object) {
  const vec3 p = position;
  const vec3 q = maxCorner_;
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
  double t = tMax;
  int face = 0;
  if (!Nearer(origin, direction, t, face)) return false;
  FillHit(origin, direction, t, face, hit);
  return true;
}

void Cube::FillHit(vec3 origin, vec3 direction, double t, int face, Hit& hit) const {
  hit.t = t;
  hit.point = PointOnSlabFace(origin, direction, t, face, position_, maxCorner_);
  hit.normal = faces_[face].Normal();
  hit.material = &material_;
  hit.object = object_;
  hit.light = false;
}

}  // namespace glint
