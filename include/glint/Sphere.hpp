// A sphere with a material: O1 and O2 of the canonical scene.
#pragma once

#include "glint/Hit.hpp"
#include "glint/Material.hpp"
#include "glint/Math.hpp"

namespace glint {

class Sphere {
 public:
  Sphere(vec3 centre, double radius, const Material& material, int object);

  // Closest hit with t in (0, tMax), from outside or inside. The hit point is projected
  // back onto the surface, so round-off cannot leave it inside or outside the sphere.
  bool Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const;
  // Any hit with t in (0, tMax): for shadow rays.
  bool IntersectAny(vec3 origin, vec3 direction, double tMax) const;

  vec3 Centre() const { return centre_; }
  double Radius() const { return radius_; }
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

}  // namespace glint
