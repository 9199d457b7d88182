// No heap allocation per ray: once a thread's RayTree has grown to the size a pixel
// needs, rendering more pixels allocates nothing. Counted by replacing operator new
// for this test binary.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "glint/camera/Camera.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/TestScenes.hpp"

namespace {
std::atomic<long> gAllocations{0};
}

void* operator new(std::size_t size) {
  gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace glint {
namespace {

long AllocationsWhileRendering(const Integrator& integrator, const Camera& camera, int spp) {
  RayTree trees;
  RenderStats stats;
  Pixel pixel;
  // Warm up: the tree grows to what these pixels need.
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      Sampler sampler(Pcg32::ForPixel(1, static_cast<std::uint64_t>(y * 16 + x)));
      pixel.Render(camera, x * 2, y * 2, spp, integrator, sampler, trees, stats);
    }
  }
  const long before = gAllocations.load();
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      Sampler sampler(Pcg32::ForPixel(1, static_cast<std::uint64_t>(y * 16 + x)));
      pixel.Render(camera, x * 2, y * 2, spp, integrator, sampler, trees, stats);
    }
  }
  return gAllocations.load() - before;
}

TEST(Allocation, NoHeapAllocationPerRayOnTheHotPath) {
  const Scene scene = testing::CanonicalScene();
  const Camera camera(scene.wall, scene.camera, 32, 32);
  EXPECT_EQ(AllocationsWhileRendering(WhittedIntegrator(scene, 10), camera, 4), 0);
  MonteCarloOptions o;
  o.walls = MonteCarloOptions::Walls::Diffuse;
  o.branches = 2;
  EXPECT_EQ(AllocationsWhileRendering(MonteCarloIntegrator(scene, o), camera, 16), 0);
  // The counter does count: a vector allocates.
  const long before = gAllocations.load();
  std::vector<int> v(10);
  EXPECT_GT(gAllocations.load() - before, 0);
}

}  // namespace
}  // namespace glint
