#include "glint/Light.hpp"

namespace glint {

Light::Light(Rectangle shape, Colour radiance, int object)
    : shape_(shape), radiance_(radiance), object_(object) {}

LightSample Light::SampleLi(vec3 p, double u, double v) const {
  LightSample s{SamplePoint(u, v), vec3(0.0), 0.0, 0.0, Colour(0.0)};
  const vec3 toLight = s.point - p;
  const double r2 = glm::dot(toLight, toLight);
  if (r2 == 0.0) return s;
  s.distance = std::sqrt(r2);
  s.wi = toLight / s.distance;
  const double cosLight = -glm::dot(s.wi, shape_.Normal());
  if (cosLight <= 0.0) return s;  // p is behind the emitting side
  s.pdf = r2 / (cosLight * shape_.Area());
  s.Le = radiance_;
  return s;
}

double Light::PdfLi(vec3 p, vec3 y) const {
  const vec3 toLight = y - p;
  const double r2 = glm::dot(toLight, toLight);
  const double cosLight = -glm::dot(toLight, shape_.Normal()) / std::sqrt(r2);
  return cosLight > 0.0 ? r2 / (cosLight * shape_.Area()) : 0.0;
}

}  // namespace glint
