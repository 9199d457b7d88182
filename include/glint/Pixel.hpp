// One pixel of the Camera: it shoots its rays through random points inside itself,
// has the integrator grow their ray trees, and keeps their equally weighted mean
// (a box filter; each first ray has importance 1/N).
#pragma once

#include <cstdint>

#include "glint/Integrator.hpp"
#include "glint/Math.hpp"
#include "glint/RayTree.hpp"
#include "glint/RenderStats.hpp"
#include "glint/Rng.hpp"

namespace glint {

class Camera;

class Pixel {
 public:
  // Renders pixel (x, y) with `rays` rays. The trees are built in `trees`; with
  // keepTrees all of them are left there (for drawing), otherwise the storage is
  // reused from one ray to the next so that memory does not grow with N.
  void Render(const Camera& camera, int x, int y, int rays, const Integrator& integrator,
              Pcg32& rng, RayTree& trees, RenderStats& stats, bool keepTrees = false);

  Colour Radiance() const { return radiance_; }

 private:
  Colour radiance_{0.0};
};

}  // namespace glint
