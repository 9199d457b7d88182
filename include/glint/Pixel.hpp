// One pixel of the Camera: it shoots its rays through random points inside itself,
// has the integrator grow their ray trees, and keeps their equally weighted mean
// (a box filter; each first ray has importance 1/N). A progressive render adds passes;
// the pixel's radiance is the mean of all its finite samples.
#pragma once

#include <atomic>
#include <cstdint>

#include "glint/Integrator.hpp"
#include "glint/Math.hpp"
#include "glint/PixelShaft.hpp"
#include "glint/RayTree.hpp"
#include "glint/RenderStats.hpp"
#include "glint/Rng.hpp"

namespace glint {

class Camera;

class Pixel {
 public:
  // Adds a pass of `rays` rays through pixel (x, y). The trees are built in `trees`;
  // with keepTrees all of them are left there (for drawing), otherwise the storage is
  // reused from one ray to the next so that memory does not grow with N. A NaN or Inf
  // sample is counted and dropped; the pass averages the finite ones.
  // If `cancel` turns true the pass ends early with the rays traced so far.
  void Render(const Camera& camera, int x, int y, int rays, const Integrator& integrator,
              Pcg32& rng, RayTree& trees, RenderStats& stats, bool keepTrees = false,
              const std::atomic<bool>* cancel = nullptr);

  // What the pixel knows of its rays in advance (Camera::PrepareShafts); nothing until then.
  void SetShaft(PixelShaft shaft) { shaft_ = shaft; }
  PixelShaft Shaft() const { return shaft_; }

  Colour Radiance() const { return samples_ > 0 ? sum_ / static_cast<double>(samples_) : sum_; }
  std::uint64_t Samples() const { return samples_; }
  // Forgets the samples (not the shaft, which depends on the geometry only).
  void Clear() {
    sum_ = Colour(0.0);
    samples_ = 0;
  }

 private:
  Colour sum_{0.0};  // sum of the finite samples' colours
  std::uint64_t samples_ = 0;
  PixelShaft shaft_;
};

}  // namespace glint
