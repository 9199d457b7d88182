// Snell's law and the Fresnel equations for a dielectric boundary. Normals point to
// the outside (the medium of index 1); `ior` is the refractive index inside.
#pragma once

#include <cstdint>
#include <optional>

#include "glint/core/Math.hpp"

namespace glint {

// What a ray along d meets at a dielectric surface with outward normal n: the refracted
// direction (nothing for total internal reflection) and the unpolarised Fresnel
// reflectance F = (r_par^2 + r_perp^2) / 2 (1 for total internal reflection), computed
// together from one cos_i and cos_t. A ray from inside (dot(d, n) > 0) sees the index
// ratio flipped.
struct DielectricInterface {
  std::optional<vec3> refracted;
  double reflectance;
};
DielectricInterface CrossDielectric(vec3 d, vec3 n, double ior);

// Unpolarised Fresnel reflectance for a ray arriving along d at a surface with outward
// normal n: F = (r_par^2 + r_perp^2) / 2. A ray from inside (dot(d, n) > 0) sees the
// index ratio flipped. Returns 1 for total internal reflection.
double FresnelDielectric(vec3 d, vec3 n, double ior);

// Reflectance at normal incidence, ((n - 1) / (n + 1))^2.
double FresnelNormalIncidence(double ior);

// Which reflectance glass has: the Fresnel equations, or the design's small-angle
// approximation (lecture 2), the normal-incidence reflectance at every angle.
enum class FresnelModel : std::uint8_t { Exact, SmallAngle };

// The reflectance of `glass` (index ior) under `model`. The small-angle approximation
// keeps total internal reflection (F = 1), where no refracted ray exists.
inline double GlassReflectance(const DielectricInterface& glass, double ior, FresnelModel model) {
  if (model == FresnelModel::Exact || glass.reflectance == 1.0) return glass.reflectance;
  return FresnelNormalIncidence(ior);
}

// Refracted direction (unit) for a ray along d, or nothing for total internal
// reflection. Uses a safe square root; works from either side of the surface.
std::optional<vec3> Refract(vec3 d, vec3 n, double ior);

}  // namespace glint
