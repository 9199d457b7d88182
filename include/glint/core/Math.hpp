// Vector types, constants and the small numeric helpers every file shares.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace glint {

using vec3 = glm::dvec3;    // points and directions, in metres
using Colour = glm::dvec3;  // linear RGB radiance, importance or reflectance

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInvPi = 1.0 / kPi;
inline constexpr double kInfinity = 1e300;

inline double MaxComponent(vec3 v) {
  return std::max({v.x, v.y, v.z});
}
inline double MaxAbsComponent(vec3 v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
inline bool IsFinite(vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline double Luminance(Colour c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// sqrt that never returns NaN for a tiny negative argument left by round-off.
inline double SafeSqrt(double x) {
  return std::sqrt(std::max(0.0, x));
}

// Relative scale of the offset that moves a spawned ray's origin off the surface it
// leaves. Double-precision intersection errors are ~1e-15 |p|; this leaves six orders
// of magnitude of margin and is still far below a pixel's footprint.
inline constexpr double kOriginOffset = 1e-9;

// Moves a hit point p off its surface (unit normal n) to the side that direction w
// leaves on, by an amount that scales with |p| (pbrt-v4's OffsetRayOrigin idea).
inline vec3 OffsetRayOrigin(vec3 p, vec3 n, vec3 w) {
  const double d = kOriginOffset * (1.0 + MaxAbsComponent(p));
  return glm::dot(w, n) >= 0.0 ? p + d * n : p - d * n;
}

// The normal on the side that a ray with direction d arrives from: `normal` or its
// opposite. Light is gathered, and rays leave, on that side.
inline vec3 FacingNormal(vec3 d, vec3 normal) {
  return glm::dot(d, normal) < 0.0 ? normal : -normal;
}

// Mirror reflection of the incident direction d about the unit normal n.
inline vec3 Reflect(vec3 d, vec3 n) {
  return d - 2.0 * glm::dot(d, n) * n;
}

}  // namespace glint
