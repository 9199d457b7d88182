// The loop of passes, in one place: every pass of `glint render`, `converge` and `view`
// is rendered here. A pass has a number (its pixels' random streams), a first sample
// (where a sobol sequence goes on from) and its rays per pixel; the loop numbers the
// passes, times them and adds their counters, and spreads each over the cluster's ranks
// (Cluster::RenderPass, which hands chunks of pixels to Camera::RenderChunks). How many
// rays the next pass has is the caller's schedule: PassSchedule for --time, a ladder's
// rung for converge, doubling toward a frame time for view.
#pragma once

#include <cstdint>
#include <functional>

#include "glint/camera/Camera.hpp"
#include "glint/camera/Integrator.hpp"
#include "glint/camera/RenderStats.hpp"
#include "job/Cluster.hpp"

namespace glint {

class PassLoop {
 public:
  struct Pass {
    int rays = 0;
    double seconds = 0.0;  // wall time
    RenderStats stats;
  };

  // `options` gives every pass's seed, sampler, threads, cancel flag and progress;
  // `cluster` must outlive the loop (a default Cluster: this process alone).
  PassLoop(Camera& camera, const Integrator& integrator, const RenderOptions& options,
           const Cluster& cluster);

  // Renders pass number Passes(), from sample Spp(), with `rays` rays per pixel, and adds
  // its counters to Stats() (work done counts, finished or not). It is a pass of the
  // render only once Count()ed: one a cancel cut short is not. `betweenBatches`, if any,
  // runs between batches of chunks (a checkpoint; Cluster::RenderPass).
  Pass Render(int rays, const std::function<void()>& betweenBatches = {});
  // The pass just rendered ran to its end: it counts.
  void Count(const Pass& pass);

  // A resumed render (a checkpoint's): the passes it holds, and whether the pass under
  // way keeps the pixels it had done (RenderOptions::skipDone).
  void Resume(std::uint32_t passes, std::uint64_t spp, const RenderStats& stats, bool skipDone);

  std::uint32_t Passes() const { return passes_; }
  std::uint64_t Spp() const { return spp_; }  // rays per pixel of the counted passes
  // Every pass's counters so far, the pass under way's included (between its batches).
  RenderStats Stats() const {
    RenderStats s = stats_;
    s += current_;
    return s;
  }

 private:
  Camera& camera_;
  const Integrator& integrator_;
  RenderOptions options_;
  const Cluster& cluster_;
  std::uint32_t passes_ = 0;
  std::uint64_t spp_ = 0;
  RenderStats stats_;    // of the passes rendered before the one under way
  RenderStats current_;  // of the pass under way
};

}  // namespace glint
