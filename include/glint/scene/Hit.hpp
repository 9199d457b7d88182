// The closest intersection of a ray with the scene.
#pragma once

#include "glint/core/Math.hpp"
#include "glint/scene/Material.hpp"

namespace glint {

struct Hit {
  double t = kInfinity;
  vec3 point{0.0};
  // Unit geometric normal on the "outside" of the surface: away from a solid object,
  // into the room for a wall, downward for the ceiling light.
  vec3 normal{0.0};
  const Material* material = nullptr;
  int object = -1;     // index into Scene::ObjectName
  bool light = false;  // the area light was hit
};

}  // namespace glint
