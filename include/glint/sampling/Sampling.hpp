// Sampling routines, each beside its density (pbrt-v4 style). Directions are sampled
// in a local frame whose z axis is the lobe's axis; Frame takes them to the world.
#pragma once

#include "glint/core/Math.hpp"
#include "glint/core/SinCos.hpp"

namespace glint {

// An orthonormal basis (s, t, n) around a unit vector n (Duff et al. 2017, branchless).
struct Frame {
  vec3 s, t, n;

  static Frame FromZ(vec3 z) {
    const double sign = std::copysign(1.0, z.z);
    const double a = -1.0 / (sign + z.z);
    const double b = z.x * z.y * a;
    return {vec3(1.0 + sign * z.x * z.x * a, sign * b, -sign * z.x),
            vec3(b, sign + z.y * z.y * a, -z.y), z};
  }
  vec3 ToWorld(vec3 v) const { return v.x * s + v.y * t + v.z * n; }
  vec3 ToLocal(vec3 v) const { return {glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)}; }
};

// Cosine-weighted hemisphere around +z (Malley's method): p(w) = cos(theta) / pi.
inline vec3 SampleCosineHemisphere(double u1, double u2) {
  const double r = std::sqrt(u1);
  const SinCos phi = SinCosTurns(u2);  // the azimuth 2 pi u2
  return {r * phi.cos, r * phi.sin, SafeSqrt(1.0 - u1)};
}
// A cosine-sampled direction around the unit normal n, unit length (Frame, then
// normalised: the frame's rounding leaves it within a few ulp of 1).
inline vec3 SampleCosineDirection(const Frame& frame, double u1, double u2) {
  return glm::normalize(frame.ToWorld(SampleCosineHemisphere(u1, u2)));
}
inline vec3 SampleCosineDirection(vec3 n, double u1, double u2) {
  return SampleCosineDirection(Frame::FromZ(n), u1, u2);
}
inline double CosineHemispherePdf(double cosTheta) {
  return cosTheta > 0.0 ? cosTheta * kInvPi : 0.0;
}

// Whether CosinePower raises to n by squaring: a whole n in [0, 1024].
inline bool PowerBySquaring(double n) {
  return n >= 0.0 && n <= 1024.0 && static_cast<double>(static_cast<unsigned>(n)) == n;
}

// c^n for a lobe's cos^n(alpha), c >= 0. Scenes give whole exponents (the canonical
// n = 100): by repeated squaring those take 8 multiplications instead of a call to
// pow. Each squaring doubles the relative error, so it stays below n ulp: 1e-14 for
// n = 100, 2.3e-13 at the largest n taken this way. Any other exponent goes to pow.
inline double CosinePower(double c, double n) {
  if (PowerBySquaring(n)) {
    double power = 1.0;
    auto k = static_cast<unsigned>(n);
    for (double base = c; k != 0; k >>= 1U, base *= base) {
      if ((k & 1U) != 0) power *= base;
    }
    return power;
  }
  return std::pow(c, n);
}

// The lobe cos^n(alpha) around +z, on the hemisphere alpha < pi/2:
// p(w) = (n + 1) / (2 pi) cos^n(alpha), by inverting its CDF: cos(alpha) = u1^(1/(n+1)).
inline vec3 SamplePowerCosine(double n, double u1, double u2) {
  // 1 - u1 lies in (0, 1], so cos(alpha) > 0 and the power is finite for any n >= 0.
  const double cosAlpha = std::pow(1.0 - u1, 1.0 / (n + 1.0));
  const double sinAlpha = SafeSqrt(1.0 - cosAlpha * cosAlpha);
  const SinCos phi = SinCosTurns(u2);
  return {sinAlpha * phi.cos, sinAlpha * phi.sin, cosAlpha};
}
inline double PowerCosinePdf(double n, double cosAlpha) {
  return cosAlpha > 0.0 ? (n + 1.0) / (2.0 * kPi) * CosinePower(cosAlpha, n) : 0.0;
}
// The same density for a direction SamplePowerCosine drew with this u1, whose z is
// cosAlpha = (1 - u1)^(1/(n+1)): then cos^n(alpha) = (1 - u1) / cos(alpha), no power.
inline double PowerCosinePdfOfSample(double n, double u1, double cosAlpha) {
  return (n + 1.0) / (2.0 * kPi) * ((1.0 - u1) / cosAlpha);
}

// Power heuristic (beta = 2) for a strategy with density f against one with density g,
// each density already multiplied by its number of samples (Veach 1997, eq. 9.13).
inline double PowerHeuristic(double f, double g) {
  if (std::isinf(f)) return 1.0;
  const double f2 = f * f;
  const double g2 = g * g;
  return f2 + g2 > 0.0 ? f2 / (f2 + g2) : 0.0;
}

}  // namespace glint
