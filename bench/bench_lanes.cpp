// The SIMD lanes alone, data in L1, on each target this CPU runs (0 scalar, 1 sse4, 2 avx2,
// 3 avx512): a roomOnly camera path's arithmetic (TerminalWallLanes: direction, wall,
// next-event estimate; no shadow ray) and the Sobol sampler's first group of numbers
// (SobolLanes). Their time per ray is the floor under a roomOnly path at this machine's
// rate (BENCHMARKS.md, "SIMD lanes"). Counter: rays/s.
#include <benchmark/benchmark.h>

#include "RaySets.hpp"
#include "glint/camera/Camera.hpp"
#include "glint/sampling/SobolLanes.hpp"
#include "glint/transport/TerminalWallLanes.hpp"

namespace glint::bench {
namespace {

constexpr SimdTarget kTargets[] = {SimdTarget::Scalar, SimdTarget::Sse4, SimdTarget::Avx2,
                                   SimdTarget::Avx512};

void WallLanes(benchmark::State& state) {
  const SimdTarget target = kTargets[state.range(0)];
  if (!SimdTargetSupported(target)) {
    state.SkipWithError("this CPU does not run the target");
    return;
  }
  const Scene& scene = CanonicalScene();
  const TerminalWallLanes lanes(scene.wall, *scene.light,
                                Camera::GeometryFor(scene.wall, scene.camera, 256, 256), target);
  RayLanes rays{};
  for (std::size_t i = 0; i < RayLanes::kMax; ++i) {
    rays.px[i] = 128.0 + 0.1 * static_cast<double>(i);
    rays.py[i] = 100.0 + 0.05 * static_cast<double>(i);
    rays.lightU[i] = 0.1 * static_cast<double>(i);
    rays.lightV[i] = 0.9 - 0.1 * static_cast<double>(i);
  }
  for (auto _ : state) {
    lanes.Trace(rays, RayLanes::kMax, Wall::kBack);
    benchmark::DoNotOptimize(rays);
    benchmark::ClobberMemory();
  }
  state.SetLabel(SimdTargetName(target));
  state.counters["rays/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * RayLanes::kMax, benchmark::Counter::kIsRate);
}
BENCHMARK(WallLanes)->DenseRange(0, 3);

void SobolLanes(benchmark::State& state) {
  const SimdTarget target = kTargets[state.range(0)];
  if (!SimdTargetSupported(target)) {
    state.SkipWithError("this CPU does not run the target");
    return;
  }
  const SobolLaneSeeds seeds{0x12345678U, {0x9abcdef0U, 0x0fedcba9U, 0x87654321U, 0x13579bdfU}};
  SobolLaneValues values{};
  std::uint32_t first = 0;
  for (auto _ : state) {
    SobolFirstGroupLanes(target, seeds, first, kSobolLanesMax, values);
    benchmark::DoNotOptimize(values);
    first += kSobolLanesMax;
  }
  state.SetLabel(SimdTargetName(target));
  state.counters["rays/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * kSobolLanesMax, benchmark::Counter::kIsRate);
}
BENCHMARK(SobolLanes)->DenseRange(0, 3);

}  // namespace
}  // namespace glint::bench
