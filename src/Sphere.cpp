#include "glint/Sphere.hpp"

namespace glint {

Sphere::Sphere(vec3 centre, double radius, const Material& material, int object)
    : centre_(centre), radius_(radius), material_(material), object_(object) {}

bool Sphere::Roots(vec3 origin, vec3 direction, double& t0, double& t1) const {
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

bool Sphere::Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const {
  double t0 = 0.0;
  double t1 = 0.0;
  if (!Roots(origin, direction, t0, t1)) return false;
  double t = t0;
  if (!(t > 0.0)) t = t1;
  if (!(t > 0.0 && t < tMax)) return false;
  const vec3 outward = glm::normalize(origin + t * direction - centre_);
  hit.t = t;
  hit.normal = outward;
  hit.point = centre_ + radius_ * outward;  // back onto the surface
  hit.material = &material_;
  hit.object = object_;
  hit.light = false;
  return true;
}

bool Sphere::IntersectAny(vec3 origin, vec3 direction, double tMax) const {
  double t0 = 0.0;
  double t1 = 0.0;
  if (!Roots(origin, direction, t0, t1)) return false;
  return (t0 > 0.0 && t0 < tMax) || (t1 > 0.0 && t1 < tMax);
}

}  // namespace glint
