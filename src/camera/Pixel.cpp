#include "glint/camera/Pixel.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "glint/camera/Camera.hpp"

namespace glint {

PixelPass Pixel::TracePass(const Camera& camera, int x, int y, int rays,
                           const Integrator& integrator, Sampler& sampler, RayTree& trees,
                           RenderStats& stats, bool keepTrees,
                           const std::atomic<bool>* cancel) const {
  if (integrator.LaneWidth(shaft_) > 0) {
    return TracePassInLanes(camera, x, y, rays, integrator, sampler, trees, stats, keepTrees,
                            cancel);
  }
  if (sampler.Kind() == SamplerKind::Sobol && integrator.FirstHitLanes(shaft_, rays)) {
    return TracePassWithFirstHits(camera, x, y, rays, integrator, sampler, trees, stats, keepTrees,
                                  cancel);
  }
  const double importance = 1.0 / rays;  // all rays of a pixel weigh the same
  PixelPass pass;
  trees.Clear();
  for (int i = 0; i < rays; ++i) {
    if (Cancelled(cancel, i)) {
      pass.complete = false;
      break;
    }
    if (!keepTrees) trees.Clear();
    sampler.StartSample(i);
    const Sample2 p = sampler.Get2D(SampleDimension::kPixel);  // a point inside the pixel
    const double px = x + p.u;
    const double py = y + p.v;
    const std::uint32_t root =
        trees.Add(CameraRay(camera.Eye(), camera.DirectionThrough(px, py), importance));
    ++stats.cameraRays;
    AddSample(integrator.Trace(trees, root, shaft_, sampler, stats), pass, stats);
  }
  return pass;
}

template <class TraceGroup>
PixelPass Pixel::TraceGroups(int rays, RayTree& trees, const std::atomic<bool>* cancel,
                             TraceGroup traceGroup, int groupRays) {
  PixelPass pass;
  trees.Clear();
  for (int first = 0; first < rays; first += groupRays) {
    int count = std::min(groupRays, rays - first);
    for (int i = first; i < first + count; ++i) {
      if (Cancelled(cancel, i)) {
        pass.complete = false;
        count = i - first;
        break;
      }
    }
    if (count > 0) traceGroup(first, count, pass);
    if (!pass.complete) break;
  }
  return pass;
}

PixelPass Pixel::TracePassInLanes(const Camera& camera, int x, int y, int rays,
                                  const Integrator& integrator, Sampler& sampler, RayTree& trees,
                                  RenderStats& stats, bool keepTrees,
                                  const std::atomic<bool>* cancel) const {
  const double importance = 1.0 / rays;
  RayLanes lanes{};
  std::array<std::array<double, kSobolLanesMax>, 4> numbers{};
  const SimdTarget target = integrator.LaneTarget();
  static_assert(RayLanes::kMax == kSobolLanesMax);
  return TraceGroups(rays, trees, cancel, [&](int first, int count, PixelPass& pass) {
    // The sampler's numbers of these rays (the pixel point, the first light point), as
    // TracePass draws them ray by ray.
    sampler.FirstGroupInLanes(first, count, target, numbers, integrator.LanesTakeLightPoint());
    for (std::size_t lane = 0; lane < static_cast<std::size_t>(count); ++lane) {
      lanes.px[lane] = x + numbers[0][lane];
      lanes.py[lane] = y + numbers[1][lane];
      lanes.lightU[lane] = numbers[2][lane];
      lanes.lightV[lane] = numbers[3][lane];
    }
    integrator.TraceLanes(lanes, count, shaft_, stats);
    // Each ray's own tree (its one node: the camera ray, ended on a terminal wall), and
    // its colour into the sum in ray order, as TracePass adds them. The sum and the
    // counters stay in registers, not in memory a lane at a time (a chain of stores and
    // loads; with MonteCarloIntegrator::TraceLanes' count for a shaft that sees the light,
    // the empty room 1.09x faster, measured together).
    const vec3 eye = camera.Eye();
    PixelPass sum = pass;
    for (std::size_t lane = 0; lane < static_cast<std::size_t>(count); ++lane) {
      if (!keepTrees) trees.Clear();
      Ray ray = LaneCameraRay(eye, lanes, lane, importance);
      ray.end = vec3(lanes.end[0][lane], lanes.end[1][lane], lanes.end[2][lane]);
      ray.object = lanes.object;
      ray.final = true;
      ray.colour = Colour(lanes.colour[0][lane], lanes.colour[1][lane], lanes.colour[2][lane]);
      trees.Add(ray);
      AddSample(ray.colour, sum, stats);
    }
    pass = sum;
    stats.cameraRays += static_cast<std::uint64_t>(count);
    stats.laneRays += static_cast<std::uint64_t>(count);
  });
}

PixelPass Pixel::TracePassWithFirstHits(const Camera& camera, int x, int y, int rays,
                                        const Integrator& integrator, Sampler& sampler,
                                        RayTree& trees, RenderStats& stats, bool keepTrees,
                                        const std::atomic<bool>* cancel) const {
  if (!keepTrees && integrator.TracesGroupsFromLanes()) {
    return TracePassInGroups(camera, x, y, rays, integrator, sampler, trees, stats, cancel);
  }
  const double importance = 1.0 / rays;
  RayLanes lanes{};
  Sampler::FirstGroups numbers{};
  const SimdTarget target = integrator.LaneTarget();
  return TraceGroups(rays, trees, cancel, [&](int first, int count, PixelPass& pass) {
    // The sampler's first numbers of these rays and their first hits, in lanes; then
    // each ray as TracePass traces it, its sample started from the lane's numbers.
    sampler.FirstGroupsInLanes(first, count, target, numbers);
    for (std::size_t lane = 0; lane < static_cast<std::size_t>(count); ++lane) {
      lanes.px[lane] = x + numbers[0][lane];
      lanes.py[lane] = y + numbers[1][lane];
    }
    integrator.FindFirstHits(lanes, count);
    for (int lane = 0; lane < count; ++lane) {
      const auto j = static_cast<std::size_t>(lane);
      if (!keepTrees) trees.Clear();
      sampler.StartSampleWith(first + lane, numbers, j);
      const std::uint32_t root = trees.Add(LaneCameraRay(camera.Eye(), lanes, j, importance));
      ++stats.cameraRays;
      if (lanes.closest[j] >= 0.0) ++stats.laneRays;  // its first hit from the lanes
      AddSample(integrator.TraceFromLane(trees, root, shaft_, lanes, lane, sampler, stats), pass,
                stats);
    }
  });
}

PixelPass Pixel::TracePassInGroups(const Camera& camera, int x, int y, int rays,
                                   const Integrator& integrator, Sampler& sampler, RayTree& trees,
                                   RenderStats& stats, const std::atomic<bool>* cancel) const {
  const double importance = 1.0 / rays;
  constexpr int kSets = Integrator::kMaxGroupRays / RayLanes::kMax;
  std::array<RayLanes, kSets> lanes;
  std::array<Sampler::FirstGroups, kSets> numbers;
  std::array<Colour, Integrator::kMaxGroupRays> colours;
  const SimdTarget target = integrator.LaneTarget();
  const auto traceGroup = [&](int first, int count, PixelPass& pass) {
    // The sampler's first numbers of these rays and their first hits, in lanes of
    // RayLanes::kMax; then the group's rays together, their colours into the sum in ray
    // order.
    for (int set = 0; set * RayLanes::kMax < count; ++set) {
      const auto s = static_cast<std::size_t>(set);
      const int setFirst = set * RayLanes::kMax;
      const int n = std::min(RayLanes::kMax, count - setFirst);
      sampler.FirstGroupsInLanes(first + setFirst, n, target, numbers[s]);
      for (std::size_t lane = 0; lane < static_cast<std::size_t>(n); ++lane) {
        lanes[s].px[lane] = x + numbers[s][0][lane];
        lanes[s].py[lane] = y + numbers[s][1][lane];
      }
      integrator.FindFirstHits(lanes[s], n);
    }
    trees.Clear();
    const vec3 eye = camera.Eye();
    std::uint64_t inLanes = 0;
    for (int i = 0; i < count; ++i) {
      const RayLanes& set = lanes[static_cast<std::size_t>(i / RayLanes::kMax)];
      const auto j = static_cast<std::size_t>(i % RayLanes::kMax);
      trees.Add(LaneCameraRay(eye, set, j, importance));
      inLanes += set.closest[j] >= 0.0 ? 1U : 0U;
    }
    stats.cameraRays += static_cast<std::uint64_t>(count);
    stats.laneRays += inLanes;
    integrator.TraceGroupFromLanes(trees, 0, count, shaft_, lanes.data(), sampler, first,
                                   numbers.data(), stats, colours.data());
    PixelPass sum = pass;
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
      AddSample(colours[i], sum, stats);
    }
    pass = sum;
  };
  return TraceGroups(rays, trees, cancel, traceGroup, integrator.GroupRays());
}

}  // namespace glint
