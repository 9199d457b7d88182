#include "glint/scene/Light.hpp"

namespace glint {

Light::Light(Rectangle shape, Colour radiance, int object)
    : shape_(shape), radiance_(radiance), object_(object) {}

double Light::PdfLi(vec3 p, vec3 y) const {
  const vec3 toLight = y - p;
  const double r2 = glm::dot(toLight, toLight);
  const double cosLight = -glm::dot(toLight, shape_.Normal()) / std::sqrt(r2);
  return cosLight > 0.0 ? r2 / (cosLight * shape_.Area()) : 0.0;
}

}  // namespace glint
