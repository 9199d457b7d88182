// The room: five Rectangles W1..W5 (left, ceiling, right, floor, back) of the cube
// [Position, Position + Size]^3, with normals into the room. The front is open.
// The rectangles lie on the planes of a box, so rays meet them by the slab test.
#pragma once

#include <array>

#include "glint/Hit.hpp"
#include "glint/Material.hpp"
#include "glint/Rectangle.hpp"
#include "glint/Slabs.hpp"

namespace glint {

class Wall {
 public:
  enum Side { kLeft = 0, kCeiling, kRight, kFloor, kBack, kSides };

  Wall() : Wall(vec3(0.0), 1.0, {}) {}
  // materials[i] and object ids first + i belong to side i.
  Wall(vec3 position, double size, const std::array<Material, kSides>& materials,
       int firstObject = 0);

  bool Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const;

  // The two halves of Intersect, for the scene's closest-hit loop: Nearer lowers t to
  // the distance of the wall the ray meets if that is in (0, t) and says which side it
  // is; FillHit then records the hit.
  bool Nearer(vec3 origin, vec3 direction, double& t, int& side) const;
  void FillHit(vec3 origin, vec3 direction, double t, int side, Hit& hit) const;

  vec3 Position() const { return position_; }
  double Size() const { return size_; }
  vec3 Centre() const { return position_ + vec3(0.5 * size_); }
  const Rectangle& Face(int side) const { return faces_[side]; }
  const Material& GetMaterial(int side) const { return materials_[side]; }
  // True if p lies inside the room (closed box).
  bool Contains(vec3 p, double tolerance = 0.0) const;

 private:
  // The wall side on each face of the box (IntersectSlabs' order); the front is open.
  static constexpr std::array<int, 6> kSideOfFace = {kLeft, kRight, kFloor, kCeiling, kBack, -1};

  vec3 position_;
  vec3 maxCorner_;
  double size_;
  std::array<Material, kSides> materials_;
  std::array<Rectangle, kSides> faces_;
  int firstObject_;
};

// Inline: this runs for every ray.
inline bool Wall::Nearer(vec3 origin, vec3 direction, double& t, int& side) const {
  const vec3 o = origin;
  const vec3 d = direction;
  if (Contains(o)) {
    // From inside the room the ray leaves through the face that comes first among the
    // three it heads for: along axis a at t_a = gap_a / |d_a|. Compare t_b < t_a as
    // gap_b |d_a| < gap_a |d_b| (no division; d_b = 0 means t_b = infinity, which never
    // comes sooner), then divide once for the winner.
    const vec3 gap(d.x > 0.0 ? maxCorner_.x - o.x : o.x - position_.x,
                   d.y > 0.0 ? maxCorner_.y - o.y : o.y - position_.y,
                   d.z > 0.0 ? maxCorner_.z - o.z : o.z - position_.z);
    const vec3 speed = glm::abs(d);
    const auto sooner = [&](int b, int a) {
      return speed[b] > 0.0 && (speed[a] == 0.0 || gap[b] * speed[a] < gap[a] * speed[b]);
    };
    int axis = 0;
    if (sooner(1, axis)) axis = 1;
    if (sooner(2, axis)) axis = 2;
    const int face = 2 * axis + (d[axis] > 0.0 ? 1 : 0);
    const double tHit = gap[axis] / speed[axis];
    if (kSideOfFace[face] < 0 || !(tHit > 0.0 && tHit < t)) return false;  // out the front
    t = tHit;
    side = kSideOfFace[face];
    return true;
  }
  // From outside (the camera's rays): two-sided rectangles on the box's faces, so the
  // first face crossing ahead of the origin that is not the open front. A camera ray
  // enters through the front (tNear) and meets a wall where it leaves (tFar).
  const SlabCrossing c = IntersectSlabs(o, d, position_, maxCorner_);
  if (!c.hit) return false;
  int face = -1;
  double tHit = 0.0;
  if (c.tNear > 0.0 && kSideOfFace[c.nearFace] >= 0) {
    face = c.nearFace;
    tHit = c.tNear;
  } else if (c.tFar > 0.0 && kSideOfFace[c.farFace] >= 0) {
    face = c.farFace;
    tHit = c.tFar;
  }
  if (face < 0 || !(tHit < t)) return false;
  t = tHit;
  side = kSideOfFace[face];
  return true;
}

inline bool Wall::Contains(vec3 p, double tolerance) const {
  const vec3 lo = position_ - vec3(tolerance);
  const vec3 hi = maxCorner_ + vec3(tolerance);
  return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
}

}  // namespace glint
