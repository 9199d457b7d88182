// The render job: the passes of one render (RunPasses), with its time budget,
// checkpoints and resume, over this process's threads or an MPI job's ranks.
#pragma once

#include <cstdint>

#include "glint/camera/Camera.hpp"
#include "glint/camera/Integrator.hpp"
#include "glint/camera/RenderStats.hpp"
#include "job/Cluster.hpp"
#include "job/RenderSetup.hpp"

namespace glint {

struct RenderResult {
  RenderStats stats;  // all the render's work, a resumed render's earlier sessions too
  // A resumed render: what its checkpoint held (the work of the earlier sessions), so that
  // stats - resumed is what this session traced.
  RenderStats resumed;
  std::uint32_t resumedPasses = 0;
  double seconds = 0.0;
  std::uint32_t passes = 0;
  std::uint64_t spp = 0;  // rays per pixel of the finished passes
  bool interrupted = false;
};

// One pass, or passes until args.timeBudget would be overspent.
RenderResult RunPasses(Camera& camera, const Integrator& integrator, const RenderArgs& args,
                       const RenderSetup& s);

}  // namespace glint
