// The normalised Phong BRDF of the design, f(psi) = rho (n + 2) / (2 pi) (R . psi)^n,
// with R the mirror direction of the incident ray d about the normal, and its sampler,
// proportional to cos^n around R: p(psi) = (n + 1) / (2 pi) (R . psi)^n.
// Importance of a sample = f cos(theta) / p = rho (n + 2) / (n + 1) cos(theta), and 0 for
// a sample below the surface.
#pragma once

#include "glint/sampling/Sampling.hpp"
#include "glint/scene/Material.hpp"

namespace glint {

struct PhongSample {
  vec3 direction;  // psi, unit
  double pdf;      // solid-angle density of psi
  Colour weight;   // f cos(theta) / pdf, zero below the surface
};

// d: incident direction (toward the surface); n: unit normal on the side d comes from.
inline PhongSample SamplePhong(const Material& m, vec3 d, vec3 n, double u1, double u2) {
  const vec3 r = Reflect(d, n);
  const vec3 local = SamplePowerCosine(m.exponent, u1, u2);
  const vec3 psi = glm::normalize(Frame::FromZ(r).ToWorld(local));
  const double cosTheta = glm::dot(n, psi);
  const Colour weight = cosTheta > 0.0
                            ? m.reflectance * ((m.exponent + 2.0) / (m.exponent + 1.0) * cosTheta)
                            : Colour(0.0);
  return {psi, PowerCosinePdfOfSample(m.exponent, u1, local.z), weight};
}

inline double PhongPdf(const Material& m, vec3 d, vec3 n, vec3 psi) {
  return PowerCosinePdf(m.exponent, glm::dot(Reflect(d, n), psi));
}

inline Colour PhongBrdf(const Material& m, vec3 d, vec3 n, vec3 psi) {
  const double cosAlpha = glm::dot(Reflect(d, n), psi);
  if (cosAlpha <= 0.0 || glm::dot(n, psi) <= 0.0) return Colour(0.0);
  return m.reflectance * ((m.exponent + 2.0) / (2.0 * kPi) * CosinePower(cosAlpha, m.exponent));
}

// Both at once, as next-event estimation with MIS needs them: one mirror direction and
// one power cos^n(alpha) instead of two. Equal to PhongBrdf and PhongPdf.
struct PhongValue {
  Colour f;
  double pdf;
};
inline PhongValue EvaluatePhong(const Material& m, vec3 d, vec3 n, vec3 psi) {
  const double cosAlpha = glm::dot(Reflect(d, n), psi);
  if (cosAlpha <= 0.0) return {Colour(0.0), 0.0};
  const double lobe = CosinePower(cosAlpha, m.exponent);
  const double pdf = (m.exponent + 1.0) / (2.0 * kPi) * lobe;
  if (glm::dot(n, psi) <= 0.0) return {Colour(0.0), pdf};
  return {m.reflectance * ((m.exponent + 2.0) / (2.0 * kPi) * lobe), pdf};
}

}  // namespace glint
