#include "glint/Fresnel.hpp"

namespace glint {

double FresnelDielectric(vec3 d, vec3 n, double ior) {
  if (ior == 1.0) return 0.0;  // index matched: no boundary, exactly (round-off gives ~1e-33)
  double cosI = -glm::dot(d, n);
  double eta = ior;  // n_t / n_i for a ray arriving from outside
  if (cosI < 0.0) {  // from inside: the index ratio flips
    eta = 1.0 / eta;
    cosI = -cosI;
  }
  cosI = std::min(cosI, 1.0);
  const double sin2T = (1.0 - cosI * cosI) / (eta * eta);  // Snell: sin_t = sin_i / eta
  if (sin2T >= 1.0) return 1.0;                            // total internal reflection
  const double cosT = SafeSqrt(1.0 - sin2T);
  const double rPar = (eta * cosI - cosT) / (eta * cosI + cosT);
  const double rPerp = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5 * (rPar * rPar + rPerp * rPerp);
}

double FresnelNormalIncidence(double ior) {
  const double r = (ior - 1.0) / (ior + 1.0);
  return r * r;
}

std::optional<vec3> Refract(vec3 d, vec3 n, double ior) {
  if (ior == 1.0) return d;  // index matched: undeviated, exactly
  double cosI = -glm::dot(d, n);
  double eta = ior;
  if (cosI < 0.0) {  // leaving the object: flip the normal and the ratio
    eta = 1.0 / eta;
    cosI = -cosI;
    n = -n;
  }
  cosI = std::min(cosI, 1.0);
  const double sin2T = (1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) return std::nullopt;  // total internal reflection
  const double cosT = SafeSqrt(1.0 - sin2T);
  // t = d / eta + (cos_i / eta - cos_t) n   (Snell's law in vector form)
  return glm::normalize(d / eta + (cosI / eta - cosT) * n);
}

}  // namespace glint
