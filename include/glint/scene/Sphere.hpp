// A sphere with a material: O1 and O2 of the canonical scene.
#pragma once

#include "glint/core/Math.hpp"
#include "glint/scene/Hit.hpp"
#include "glint/scene/Material.hpp"

namespace glint {

class Sphere {
 public:
  Sphere(vec3 centre, double radius, const Material& material, int object);

  // Closest hit with t in (0, tMax), from outside or inside. The hit point is projected
  // back onto the surface, so round-off cannot leave it inside or outside the sphere.
  bool Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const;
  // Whether the segment from p to p + v (v not normalised) meets the sphere at a point
  // other than its ends: the shadow-ray test, without a square root or a division for
  // the segments that pass by.
  bool IntersectsSegment(vec3 p, vec3 v) const;

  // The two halves of Intersect, for the scene's closest-hit loop: Nearer lowers t to
  // this sphere's hit distance if that is in (0, t); FillHit then records the hit.
  bool Nearer(vec3 origin, vec3 direction, double& t) const;
  void FillHit(vec3 origin, vec3 direction, double t, Hit& hit) const {
    FillHitAt(glm::normalize(origin + t * direction - centre_), t, hit);
  }
  // FillHit's record from the unit outward normal at the hit, normalize(o + t d - centre),
  // found already (the closest-hit lanes).
  void FillHitAt(vec3 outward, double t, Hit& hit) const;

  vec3 Centre() const { return centre_; }
  double Radius() const { return radius_; }
  // Support function h(n) = max over the sphere of n.x, for unit n (shaft culling).
  double Support(vec3 n) const { return glm::dot(n, centre_) + radius_; }
  const Material& GetMaterial() const { return material_; }
  int Object() const { return object_; }

 private:
  // Both roots of |o + t d - c|^2 = r^2 (d unit), t0 <= t1; false if the ray misses.
  bool Roots(vec3 origin, vec3 direction, double& t0, double& t1) const;

  vec3 centre_;
  double radius_;
  Material material_;
  int object_;
};

// Inline: these run for every ray and every sphere.

inline bool Sphere::Roots(vec3 origin, vec3 direction, double& t0, double& t1) const {
  // |f + t d|^2 = r^2 with f = o - c and |d| = 1: t^2 + 2 b t + c = 0, b = f.d.
  // The discriminant is computed as r^2 - |f - b d|^2, which keeps its precision for a
  // far origin (pbrt-v4, "Ray Tracing Gems" ch. 7).
  const vec3 f = origin - centre_;
  const double b = glm::dot(f, direction);
  const vec3 perpendicular = f - b * direction;
  const double discriminant = radius_ * radius_ - glm::dot(perpendicular, perpendicular);
  if (discriminant < 0.0) return false;
  const double c = glm::dot(f, f) - radius_ * radius_;
  // Stable roots: q = -(b + sign(b) sqrt(disc)), t0 = q, t1 = c / q.
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0) {  // origin at the centre's tangent point with b = 0 and disc = 0
    t0 = t1 = 0.0;
    return true;
  }
  t0 = q;
  t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

inline bool Sphere::Nearer(vec3 origin, vec3 direction, double& t) const {
  double t0 = 0.0;
  double t1 = 0.0;
  if (!Roots(origin, direction, t0, t1)) return false;
  const double nearest = t0 > 0.0 ? t0 : t1;
  if (!(nearest > 0.0 && nearest < t)) return false;
  t = nearest;
  return true;
}

inline bool Sphere::IntersectsSegment(vec3 p, vec3 v) const {
  // Points p + s v, s in (0, 1): a s^2 + 2 b s + c = 0 with a = v.v, b = f.v, c = f.f - r^2.
  // The discriminant b^2 - a c, times a, is r^2 a^2 - |a f - b v|^2, where a f - b v is a
  // times the part of f perpendicular to v: the stable form Roots uses, without dividing.
  const vec3 f = p - centre_;
  const double a = glm::dot(v, v);
  const double b = glm::dot(f, v);
  const vec3 perpendicular = a * f - b * v;
  const double scaled = radius_ * radius_ * a * a - glm::dot(perpendicular, perpendicular);
  if (scaled < 0.0 || a == 0.0) return false;
  const double c = glm::dot(f, f) - radius_ * radius_;
  const double q = -(b + std::copysign(std::sqrt(scaled / a), b));
  if (q == 0.0) return false;  // touches at s = 0 only
  const double s0 = q / a;
  const double s1 = c / q;
  return (s0 > 0.0 && s0 < 1.0) || (s1 > 0.0 && s1 < 1.0);
}

}  // namespace glint
