#include "glint/transport/Fresnel.hpp"

namespace glint {

DielectricInterface CrossDielectric(vec3 d, vec3 n, double ior) {
  if (ior == 1.0) return {d, 0.0};  // index matched: undeviated, no reflection, exactly
  double cosI = -glm::dot(d, n);
  double eta = ior;  // n_t / n_i for a ray arriving from outside
  if (cosI < 0.0) {  // from inside: flip the normal and the index ratio
    eta = 1.0 / eta;
    cosI = -cosI;
    n = -n;
  }
  cosI = std::min(cosI, 1.0);
  const double sin2T = (1.0 - cosI * cosI) / (eta * eta);  // Snell: sin_t = sin_i / eta
  if (sin2T >= 1.0) return {std::nullopt, 1.0};            // total internal reflection
  const double cosT = SafeSqrt(1.0 - sin2T);
  const double rPar = (eta * cosI - cosT) / (eta * cosI + cosT);
  const double rPerp = (cosI - eta * cosT) / (cosI + eta * cosT);
  // t = d / eta + (cos_i / eta - cos_t) n   (Snell's law in vector form)
  return {glm::normalize(d / eta + (cosI / eta - cosT) * n), 0.5 * (rPar * rPar + rPerp * rPerp)};
}

double FresnelDielectric(vec3 d, vec3 n, double ior) {
  return CrossDielectric(d, n, ior).reflectance;
}

double FresnelNormalIncidence(double ior) {
  const double r = (ior - 1.0) / (ior + 1.0);
  return r * r;
}

std::optional<vec3> Refract(vec3 d, vec3 n, double ior) {
  return CrossDielectric(d, n, ior).refracted;
}

}  // namespace glint
