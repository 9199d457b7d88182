#include "glint/scene/Sphere.hpp"

namespace glint {

Sphere::Sphere(vec3 centre, double radius, const Material& material, int object)
    : centre_(centre), radius_(radius), material_(material), object_(object) {}

bool Sphere::Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const {
  double t = tMax;
  if (!Nearer(origin, direction, t)) return false;
  FillHit(origin, direction, t, hit);
  return true;
}

void Sphere::FillHitAt(vec3 outward, double t, Hit& hit) const {
  hit.t = t;
  hit.normal = outward;
  hit.point = centre_ + radius_ * outward;  // back onto the surface
  hit.material = &material_;
  hit.object = object_;
  hit.light = false;
}

}  // namespace glint
