// Intersection queries on realistic rays of the canonical scene: each primitive alone,
// then the whole scene's closest hit (camera and bounce rays) and any hit (shadow rays).
// Items per second = rays per second.
#include <benchmark/benchmark.h>

#include "RaySets.hpp"

namespace glint::bench {
namespace {

const RaySet& Camera() {
  static const RaySet set = CameraRays(CanonicalScene());
  return set;
}
const RaySet& Bounce() {
  static const RaySet set = BounceRays(CanonicalScene());
  return set;
}
const RaySet& Shadow() {
  static const RaySet set = ShadowRays(CanonicalScene());
  return set;
}

// Runs query(i) over the set again and again; counts hits so that nothing is optimised away.
template <typename Query>
void Run(benchmark::State& state, const RaySet& rays, Query query) {
  std::size_t hits = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < rays.Size(); ++i) hits += query(i) ? 1 : 0;
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rays.Size()));
  state.counters["hit%"] =
      100.0 * static_cast<double>(hits) / static_cast<double>(state.iterations() * rays.Size());
}

void SphereClosest(benchmark::State& state) {
  const Sphere& sphere = CanonicalScene().spheres[0];  // O1
  const RaySet& r = Camera();
  Run(state, r, [&](std::size_t i) {
    Hit hit;
    return sphere.Intersect(r.origins[i], r.directions[i], r.tMax[i], hit);
  });
}
BENCHMARK(SphereClosest);

void SphereAny(benchmark::State& state) {
  const Sphere& sphere = CanonicalScene().spheres[0];
  const RaySet& r = Shadow();
  Run(state, r, [&](std::size_t i) {
    return sphere.IntersectsSegment(r.origins[i], r.ends[i] - r.origins[i]);
  });
}
BENCHMARK(SphereAny);

void CubeClosest(benchmark::State& state) {
  const Cube& cube = CanonicalScene().cubes[0];  // O3
  const RaySet& r = Camera();
  Run(state, r, [&](std::size_t i) {
    Hit hit;
    return cube.Intersect(r.origins[i], r.directions[i], r.tMax[i], hit);
  });
}
BENCHMARK(CubeClosest);

void CubeAny(benchmark::State& state) {
  const Cube& cube = CanonicalScene().cubes[0];
  const RaySet& r = Shadow();
  Run(state, r, [&](std::size_t i) {
    return cube.IntersectsSegment(r.origins[i], r.ends[i] - r.origins[i]);
  });
}
BENCHMARK(CubeAny);

void WallClosest(benchmark::State& state, const RaySet& (*rays)()) {
  const Wall& wall = CanonicalScene().wall;
  const RaySet& r = rays();
  Run(state, r, [&](std::size_t i) {
    Hit hit;
    return wall.Intersect(r.origins[i], r.directions[i], r.tMax[i], hit);
  });
}
BENCHMARK_CAPTURE(WallClosest, camera, &Camera);
BENCHMARK_CAPTURE(WallClosest, bounce, &Bounce);

void SceneClosest(benchmark::State& state, const RaySet& (*rays)()) {
  const Scene& scene = CanonicalScene();
  const RaySet& r = rays();
  Run(state, r, [&](std::size_t i) {
    Hit hit;
    return scene.Intersect(r.origins[i], r.directions[i], hit, true);
  });
}
BENCHMARK_CAPTURE(SceneClosest, camera, &Camera);
BENCHMARK_CAPTURE(SceneClosest, bounce, &Bounce);

void SceneAny(benchmark::State& state) {
  const Scene& scene = CanonicalScene();
  const RaySet& r = Shadow();
  Run(state, r, [&](std::size_t i) { return scene.Occluded(r.origins[i], r.ends[i]); });
}
BENCHMARK(SceneAny);

}  // namespace
}  // namespace glint::bench
