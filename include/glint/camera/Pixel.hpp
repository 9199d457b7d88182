// One pixel of the Camera: it shoots its rays through points inside itself (its sampler's),
// has the integrator grow their ray trees, and keeps their equally weighted mean
// (a box filter; each first ray has importance 1/N). A progressive render adds passes;
// the pixel's radiance is the mean of all its finite samples.
#pragma once

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "glint/camera/Integrator.hpp"
#include "glint/camera/PixelShaft.hpp"
#include "glint/camera/RayTree.hpp"
#include "glint/camera/RenderStats.hpp"
#include "glint/core/Math.hpp"
#include "glint/sampling/Sampler.hpp"

namespace glint {

class Camera;

// What one pass of a pixel brought: the sum of its finite samples' colours, their number,
// and whether the pass ran to its end (a cancel can cut it short).
struct PixelPass {
  Colour sum{0.0};
  std::uint64_t samples = 0;
  bool complete = true;
};

class Pixel {
 public:
  // Traces a pass of `rays` rays through pixel (x, y) and returns it, leaving the pixel as
  // it was. The trees are built in `trees`; with keepTrees all of them are left there
  // (for drawing), otherwise the storage is reused from one ray to the next so that
  // memory does not grow with N. A NaN or Inf sample is counted and dropped.
  // If `cancel` turns true the pass ends early with the rays traced so far.
  PixelPass TracePass(const Camera& camera, int x, int y, int rays, const Integrator& integrator,
                      Sampler& sampler, RayTree& trees, RenderStats& stats, bool keepTrees = false,
                      const std::atomic<bool>* cancel = nullptr) const;
  // Adds a pass: its sum to the pixel's, in pass order (so that a pass traced elsewhere,
  // another thread or another process, gives the same bits). A complete pass counts.
  void Add(const PixelPass& pass) {
    sum_ += pass.sum;
    samples_ += pass.samples;
    passes_ += pass.complete ? 1U : 0U;
  }
  // TracePass, then Add.
  void Render(const Camera& camera, int x, int y, int rays, const Integrator& integrator,
              Sampler& sampler, RayTree& trees, RenderStats& stats, bool keepTrees = false,
              const std::atomic<bool>* cancel = nullptr) {
    Add(TracePass(camera, x, y, rays, integrator, sampler, trees, stats, keepTrees, cancel));
  }

  // What the pixel knows of its rays in advance (Camera::PrepareShafts); nothing until then.
  void SetShaft(PixelShaft shaft) { shaft_ = shaft; }
  PixelShaft Shaft() const { return shaft_; }

  // The camera rays' mean, plus light tracing's splats (already divided by the light
  // paths per camera ray: LightTracer).
  Colour Radiance() const {
    const Colour total = sum_ + SplatColour();
    return samples_ > 0 ? total / static_cast<double>(samples_) : total;
  }

  // Light tracing's contributions to this pixel (--caustics light), from any thread: in
  // fixed point, units of kSplatUnit, because integer sums are the same in whatever
  // order the threads, chunks and ranks add them (a double's are not). A splat's
  // rounding, 2^-33 at most, is 1e-9 of a sample's typical colour. Returns false, adding
  // nothing, for a splat that is not finite or too large for the sum (|c| >= 2^30).
  static constexpr double kSplatUnit = 0x1.0p-32;
  using SplatSum = std::array<std::int64_t, 3>;
  bool AddSplat(Colour c) {
    const double limit = 0x1.0p30;
    if (!(std::abs(c.x) < limit && std::abs(c.y) < limit && std::abs(c.z) < limit)) return false;
    for (int k = 0; k < 3; ++k) {
      const auto units = static_cast<std::int64_t>(std::llround(c[k] / kSplatUnit));
      std::atomic_ref<std::int64_t>(splat_[static_cast<std::size_t>(k)])
          .fetch_add(units, std::memory_order_relaxed);
    }
    return true;
  }
  void AddSplats(const SplatSum& s) {
    for (std::size_t k = 0; k < 3; ++k) splat_[k] += s[k];
  }
  const SplatSum& Splats() const { return splat_; }
  void RestoreSplats(const SplatSum& s) { splat_ = s; }
  Colour SplatColour() const {
    return Colour(static_cast<double>(splat_[0]), static_cast<double>(splat_[1]),
                  static_cast<double>(splat_[2])) *
           kSplatUnit;
  }
  std::uint64_t Samples() const { return samples_; }
  Colour Sum() const { return sum_; }
  // Complete passes added (a checkpoint's resume traces the others).
  std::uint32_t Passes() const { return passes_; }
  // Forgets the samples (not the shaft, which depends on the geometry only).
  void Clear() {
    Restore(Colour(0.0), 0, 0);
    splat_ = {};
  }
  // The state a checkpoint saved.
  void Restore(Colour sum, std::uint64_t samples, std::uint32_t passes) {
    sum_ = sum;
    samples_ = samples;
    passes_ = passes;
  }

 private:
  // TracePass for a pixel whose rays the integrator traces in lock-step lanes
  // (Integrator::LaneWidth): the same samples, the same trees, the same bits.
  PixelPass TracePassInLanes(const Camera& camera, int x, int y, int rays,
                             const Integrator& integrator, Sampler& sampler, RayTree& trees,
                             RenderStats& stats, bool keepTrees,
                             const std::atomic<bool>* cancel) const;
  // TracePass for a pixel whose camera rays find their first hits in lanes
  // (Integrator::FirstHitLanes) and are traced on one by one: the same bits.
  PixelPass TracePassWithFirstHits(const Camera& camera, int x, int y, int rays,
                                   const Integrator& integrator, Sampler& sampler, RayTree& trees,
                                   RenderStats& stats, bool keepTrees,
                                   const std::atomic<bool>* cancel) const;
  // The same, for an integrator that traces groups of those rays at once
  // (Integrator::TracesGroupsFromLanes): the same bits.
  PixelPass TracePassInGroups(const Camera& camera, int x, int y, int rays,
                              const Integrator& integrator, Sampler& sampler, RayTree& trees,
                              RenderStats& stats, const std::atomic<bool>* cancel) const;
  // The lane passes' loop: a pass of `rays` rays in groups of `groupRays` from a cleared
  // `trees`, traceGroup(first, count, pass) for each, until a cancel (which clears
  // pass.complete and ends the group before the ray it falls on).
  template <class TraceGroup>
  static PixelPass TraceGroups(int rays, RayTree& trees, const std::atomic<bool>* cancel,
                               TraceGroup traceGroup, int groupRays = RayLanes::kMax);
  // The camera ray of lane j of `lanes`, whose direction the lanes found (CameraRay).
  static Ray LaneCameraRay(vec3 eye, const RayLanes& lanes, std::size_t j, double importance) {
    return CameraRay(eye, vec3(lanes.direction[0][j], lanes.direction[1][j], lanes.direction[2][j]),
                     importance);
  }
  // A camera ray's tree root: from the eye along unit `direction`, importance 1/N.
  static Ray CameraRay(vec3 eye, vec3 direction, double importance) {
    Ray ray;
    ray.start = eye;
    ray.direction = direction;
    ray.weight = Colour(importance);
    ray.importance = Colour(importance);
    ray.kind = RayKind::Camera;
    return ray;
  }
  // Whether the pass stops before ray i: a cancel, looked at every 256 rays.
  static bool Cancelled(const std::atomic<bool>* cancel, int i) {
    return cancel != nullptr && (i & 255) == 255 && cancel->load(std::memory_order_relaxed);
  }
  // Radiance() = sum_i C_i / N over the finite samples: each first ray's colour times
  // its importance 1/N. A NaN or Inf sample is counted and dropped, never averaged in;
  // dropped samples (and rays a cancel cut short) do not darken it.
  static void AddSample(Colour c, PixelPass& pass, RenderStats& stats) {
    if (!IsFinite(c)) {
      ++stats.nonFiniteSamples;
      return;
    }
    pass.sum += c;
    ++pass.samples;
  }

  Colour sum_{0.0};  // sum of the finite samples' colours
  std::uint64_t samples_ = 0;
  std::uint32_t passes_ = 0;
  SplatSum splat_{};  // light tracing's, in units of kSplatUnit
  PixelShaft shaft_;
};

}  // namespace glint
