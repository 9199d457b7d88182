// An axis-aligned cube of six Rectangles from Position (its minimum corner) and Size,
// with outward normals: O3 of the canonical scene. It may be opaque or transparent.
// Its faces lie on the planes of a box, so rays meet it by the slab test.
#pragma once

#include <array>

#include "glint/scene/Hit.hpp"
#include "glint/scene/Material.hpp"
#include "glint/scene/Rectangle.hpp"
#include "glint/scene/Slabs.hpp"

namespace glint {

class Cube {
 public:
  Cube(vec3 position, double size, const Material& material, int object);

  bool Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const;
  // Whether the segment from p to p + v (v not normalised) meets the cube between its
  // ends: the shadow-ray test.
  bool IntersectsSegment(vec3 p, vec3 v) const;

  // The two halves of Intersect, for the scene's closest-hit loop: Nearer lowers t to
  // the cube's hit distance if that is in (0, t) and says which face it is on; FillHit
  // then records the hit.
  bool Nearer(vec3 origin, vec3 direction, double& t, int& face) const;
  void FillHit(vec3 origin, vec3 direction, double t, int face, Hit& hit) const;

  vec3 Position() const { return position_; }
  vec3 MaxCorner() const { return maxCorner_; }
  // The bounding sphere's radius and its square (MissesBound; CameraHitLanes).
  double BoundRadius() const { return boundRadius_; }
  double BoundRadius2() const { return boundRadius2_; }
  double Size() const { return size_; }
  vec3 Centre() const { return centre_; }
  // Support function h(n) = max over the cube of n.x (shaft culling).
  double Support(vec3 n) const {
    return glm::dot(n, centre_) + 0.5 * size_ * (std::abs(n.x) + std::abs(n.y) + std::abs(n.z));
  }
  const Material& GetMaterial() const { return material_; }
  int Object() const { return object_; }
  // In IntersectSlabs' order: -x, +x, -y, +y, -z, +z.
  const std::array<Rectangle, 6>& Faces() const { return faces_; }

 private:
  // An early-out for the many rays that pass far from the cube.
  bool MissesBound(vec3 origin, vec3 direction, double tMax) const;

  vec3 position_;  // minimum corner
  vec3 maxCorner_;
  vec3 centre_;
  double boundRadius2_;  // squared radius of the circumscribed sphere, a little enlarged
  double boundRadius_;
  double size_;
  Material material_;
  int object_;
  std::array<Rectangle, 6> faces_;
};

// Inline: these run for every ray.

inline bool Cube::MissesBound(vec3 origin, vec3 direction, double tMax) const {
  // The ray's line passes farther than the bounding radius from the centre, or the
  // sphere lies wholly behind the origin or beyond tMax: no division needed to say so.
  const vec3 f = origin - centre_;
  const double b = glm::dot(f, direction);
  const vec3 perpendicular = f - b * direction;
  if (glm::dot(perpendicular, perpendicular) > boundRadius2_) return true;
  const double r = boundRadius_;
  return -b + r < 0.0 || -b - r > tMax;
}

inline bool Cube::Nearer(vec3 origin, vec3 direction, double& t, int& face) const {
  if (MissesBound(origin, direction, t)) return false;
  const SlabCrossing c = IntersectSlabs(origin, direction, position_, maxCorner_);
  if (!c.hit) return false;
  // From outside the first face is the entry; from inside (a glass cube) the exit.
  const bool entering = c.tNear > 0.0;
  const double tHit = entering ? c.tNear : c.tFar;
  if (!(tHit > 0.0 && tHit < t)) return false;
  t = tHit;
  face = entering ? c.nearFace : c.farFace;
  return true;
}

inline bool Cube::IntersectsSegment(vec3 p, vec3 v) const {
  // Early-out: the line passes outside the bounding sphere, |a f - b v|^2 > R^2 a^2 with
  // a = v.v, b = f.v (a times the perpendicular part of f; no division).
  const vec3 f = p - centre_;
  const double a = glm::dot(v, v);
  const vec3 perpendicular = a * f - glm::dot(f, v) * v;
  if (glm::dot(perpendicular, perpendicular) > boundRadius2_ * a * a) return false;
  // The slab test does not need a unit direction: t is then in units of v.
  const SlabCrossing c = IntersectSlabs(p, v, position_, maxCorner_);
  return c.hit && ((c.tNear > 0.0 && c.tNear < 1.0) || (c.tFar > 0.0 && c.tFar < 1.0));
}

}  // namespace glint
