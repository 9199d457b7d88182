// The room: five Rectangles W1..W5 (left, ceiling, right, floor, back) of the cube
// [Position, Position + Size]^3, with normals into the room. The front is open.
// The rectangles lie on the planes of a box, so rays meet them by the slab test.
#pragma once

#include <array>

#include "glint/scene/Hit.hpp"
#include "glint/scene/Material.hpp"
#include "glint/scene/Rectangle.hpp"
#include "glint/scene/Slabs.hpp"

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
  // The distance at which a ray from inside the room, or from in front of it through the
  // opening, leaves through wall `side`, for a ray known to leave there (Nearer's t).
  double DistanceThrough(vec3 origin, vec3 direction, int side) const;

  vec3 Position() const { return position_; }
  vec3 MaxCorner() const { return maxCorner_; }
  // The coordinate, along AxisOf(side), of wall `side`'s plane.
  double PlaneOf(int side) const {
    const int face = kFaceOfSide[static_cast<std::size_t>(side)];
    return face % 2 == 0 ? position_[face / 2] : maxCorner_[face / 2];
  }
  // The scene's object number of wall `side`.
  int ObjectOf(int side) const { return firstObject_ + side; }
  double Size() const { return size_; }
  vec3 Centre() const { return position_ + vec3(0.5 * size_); }
  // The first half of the camera's set-up rule: `eye` lies on the axis through the
  // centre of the back wall, orthogonal to it, in front of the room's open side.
  bool EyeOnAxis(vec3 eye) const;
  const Rectangle& Face(int side) const { return faces_[side]; }
  const Material& GetMaterial(int side) const { return materials_[side]; }
  // True if p lies inside the room (closed box).
  bool Contains(vec3 p, double tolerance = 0.0) const;
  // The wall side on box face `face` (IntersectSlabs' order), -1 for the open front.
  static int SideOfFace(int face) { return kSideOfFace[static_cast<std::size_t>(face)]; }
  // The axis (0 = x, 1 = y, 2 = z) that wall `side` is perpendicular to.
  static int AxisOf(int side) {
    static constexpr std::array<int, kSides> kAxisOfSide = {0, 1, 0, 1, 2};
    return kAxisOfSide[static_cast<std::size_t>(side)];
  }

 private:
  // The wall side on each face of the box (IntersectSlabs' order); the front is open.
  static constexpr std::array<int, 6> kSideOfFace = {kLeft, kRight, kFloor, kCeiling, kBack, -1};
  // Its inverse: the face (IntersectSlabs' order) of each side.
  static constexpr std::array<int, kSides> kFaceOfSide = {0, 3, 1, 2, 4};

  // Nearer's two cases for rays that pass through the room's inside.
  bool Exit(vec3 o, vec3 d, double& t, int& side) const;
  bool EntersThroughOpening(vec3 o, vec3 d) const;

  vec3 position_;
  vec3 maxCorner_;
  double size_;
  std::array<Material, kSides> materials_;
  std::array<Rectangle, kSides> faces_;
  int firstObject_;
};

// Inline: these run for every ray.

inline bool Wall::Exit(vec3 o, vec3 d, double& t, int& side) const {
  // The ray leaves through the face that comes first among the three it heads for:
  // along axis a at t_a = gap_a / |d_a|. Compare t_b < t_a as gap_b |d_a| < gap_a |d_b|
  // (no division; d_b = 0 means t_b = infinity, which never comes sooner), then divide
  // once for the winner.
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

inline double Wall::DistanceThrough(vec3 o, vec3 d, int side) const {
  // As Exit computes it: gap / |d| along the side's axis.
  const int a = AxisOf(side);
  const double gap = d[a] > 0.0 ? maxCorner_[a] - o[a] : o[a] - position_[a];
  return gap / std::abs(d[a]);
}

inline bool Wall::EntersThroughOpening(vec3 o, vec3 d) const {
  // In front of the open side, within its x and y range, heading in, and crossing the
  // front plane inside the opening: x + s d_x / |d_z| in [lo, hi] with s = o_z - hi_z,
  // written as (x - lo) |d_z| + s d_x >= 0 and (hi - x) |d_z| - s d_x >= 0 (no division).
  const vec3 lo = position_;
  const vec3 hi = maxCorner_;
  if (!(d.z < 0.0 && o.z > hi.z && o.x >= lo.x && o.x <= hi.x && o.y >= lo.y && o.y <= hi.y)) {
    return false;
  }
  const double s = o.z - hi.z;
  const double speed = -d.z;
  return (o.x - lo.x) * speed + s * d.x >= 0.0 && (hi.x - o.x) * speed - s * d.x >= 0.0 &&
         (o.y - lo.y) * speed + s * d.y >= 0.0 && (hi.y - o.y) * speed - s * d.y >= 0.0;
}

inline bool Wall::Nearer(vec3 origin, vec3 direction, double& t, int& side) const {
  const vec3 o = origin;
  const vec3 d = direction;
  // From inside the room, or from in front of it through the opening (the camera's
  // rays, by the set-up rule), the first wall is where the ray leaves the box.
  if (Contains(o) || EntersThroughOpening(o, d)) return Exit(o, d, t, side);
  // From anywhere else outside: two-sided rectangles on the box's faces, so the first
  // face crossing ahead of the origin that is not the open front.
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
