// One full pixel in each mode (the canonical numbers of rays: 64 in Monte Carlo, 4 in
// Whitted), cycling over the pixels of a 256x256 image so that every kind of path
// counts. Counters: rays/s (all kinds, as --stats counts them) and paths/s.
#include <benchmark/benchmark.h>

#include "RaySets.hpp"
#include "glint/camera/Pixel.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"

namespace glint::bench {
namespace {

void RenderPixels(benchmark::State& state, const Integrator& integrator, int spp) {
  const Scene& scene = CanonicalScene();
  Camera camera(scene.wall, scene.camera, 256, 256);
  camera.PrepareShafts(scene, integrator.ShadowLights());  // as the renderer does
  RayTree trees;
  RenderStats stats;
  int i = 0;
  for (auto _ : state) {
    Pixel pixel;
    Sampler sampler(Pcg32::ForPixel(1, static_cast<std::uint64_t>(i)));
    // Pixels in a scrambled order (an odd multiplier permutes 0..65535), so that
    // successive iterations sample the whole image.
    const auto index = static_cast<int>((static_cast<unsigned>(i) * 40503U) & 0xffffU);
    const int x = index % 256;
    const int y = index / 256;
    pixel.SetShaft(camera.PixelAt(x, y).Shaft());
    pixel.Render(camera, x, y, spp, integrator, sampler, trees, stats);
    benchmark::DoNotOptimize(pixel);
    ++i;
  }
  state.counters["rays/s"] =
      benchmark::Counter(static_cast<double>(stats.TracedRays()), benchmark::Counter::kIsRate);
  state.counters["paths/s"] =
      benchmark::Counter(static_cast<double>(stats.cameraRays), benchmark::Counter::kIsRate);
}

void PixelMonteCarlo(benchmark::State& state) {
  const MonteCarloIntegrator integrator(CanonicalScene(), {});
  RenderPixels(state, integrator, CanonicalScene().mc.spp);
}
BENCHMARK(PixelMonteCarlo);

void PixelWhitted(benchmark::State& state) {
  const WhittedIntegrator integrator(CanonicalScene(), CanonicalScene().whitted.maxDepth);
  RenderPixels(state, integrator, CanonicalScene().whitted.spp);
}
BENCHMARK(PixelWhitted);

}  // namespace
}  // namespace glint::bench
