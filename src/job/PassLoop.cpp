#include "job/PassLoop.hpp"

#include <chrono>

namespace glint {

PassLoop::PassLoop(Camera& camera, const Integrator& integrator, const RenderOptions& options,
                   const Cluster& cluster)
    : camera_(camera), integrator_(integrator), options_(options), cluster_(cluster) {}

PassLoop::Pass PassLoop::Render(int rays, const std::function<void()>& betweenBatches) {
  options_.raysPerPixel = rays;
  options_.pass = passes_;
  options_.firstSample = spp_;
  current_ = RenderStats{};
  const auto start = std::chrono::steady_clock::now();
  cluster_.RenderPass(camera_, integrator_, options_, current_, betweenBatches);
  Pass pass;
  pass.rays = rays;
  pass.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  pass.stats = current_;
  stats_ += current_;
  current_ = RenderStats{};
  return pass;
}

void PassLoop::Count(const Pass& pass) {
  ++passes_;
  spp_ += static_cast<std::uint64_t>(pass.rays);
  options_.skipDone = false;  // only the pass a resume found under way had pixels done
}

void PassLoop::Resume(std::uint32_t passes, std::uint64_t spp, const RenderStats& stats,
                      bool skipDone) {
  passes_ = passes;
  spp_ = spp;
  stats_ = stats;
  options_.skipDone = skipDone;
}

}  // namespace glint
