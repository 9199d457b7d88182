// A light-transport mode: given the root of a ray tree, it traces the ray, grows the
// tree below it and returns the ray's colour (radiance toward the camera).
#pragma once

#include <cstdint>

#include "glint/Math.hpp"
#include "glint/RayTree.hpp"
#include "glint/RenderStats.hpp"
#include "glint/Rng.hpp"

namespace glint {

class Integrator {
 public:
  Integrator() = default;
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;
  virtual ~Integrator() = default;

  // Traces tree[root] (start, direction, importance set) and fills in its colour and
  // its subtree. Returns the colour.
  virtual Colour Trace(RayTree& tree, std::uint32_t root, Pcg32& rng, RenderStats& stats) const = 0;
};

}  // namespace glint
