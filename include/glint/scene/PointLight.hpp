// A Whitted-mode point light of radiant intensity I (W/sr): it gives a surface at
// distance r, tilted by theta, the irradiance E = I cos(theta) / r^2.
#pragma once

#include "glint/core/Math.hpp"

namespace glint {

struct PointLight {
  vec3 position{0.5};
  Colour intensity{1.0};
  int object = -1;
};

}  // namespace glint
