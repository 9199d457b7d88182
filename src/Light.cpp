#include "glint/Light.hpp"

namespace glint {

Light::Light(Rectangle shape, Colour radiance, int object)
    : shape_(shape), radiance_(radiance), object_(object) {}

}  // namespace glint
