// LambertianScatterLanes: the cosine-sampled child found in SIMD lanes is the scalar
// code's (SampleCosineDirection, then OffsetRayOrigin from the hit), to the bit, on every
// target this CPU runs: for the normals of hits on every wall, sphere and cube face from
// random points of the room, and at the numbers where the sampler's sine and cosine turn
// a quarter (v = 0, 1/4, 1/2, 3/4) or the direction lies in the surface (u near 1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/sampling/Sampling.hpp"
#include "glint/transport/LambertianScatterLanes.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::SameBits;

struct Expected {
  vec3 direction, start;
};

// The numbers a sample takes: uniform, or one of the edge cases above.
Sample2 Numbers(Pcg32& rng) {
  constexpr std::array<double, 6> kU = {0.0, 0x1p-60, 0.5, 1.0 - 0x1p-53, 1.0 - 0x1p-30, 0.25};
  constexpr std::array<double, 7> kV = {0.0, 0.25, 0.5, 0.75, 1.0 - 0x1p-53, 0.125, 0x1p-60};
  Sample2 uv{rng.Uniform(), rng.Uniform()};
  if (rng.Uniform() < 0.2) uv.u = kU[rng.NextU32() % kU.size()];
  if (rng.Uniform() < 0.2) uv.v = kV[rng.NextU32() % kV.size()];
  return uv;
}

int CompareWithScalar(const Scene& scene, SimdTarget target, int groups) {
  const LambertianScatterLanes lanes(target);
  Pcg32 rng(11, 5);
  int compared = 0;
  LambertianScatterLaneData data;
  for (int g = 0; g < groups; ++g) {
    const int count = 1 + g % RayLanes::kMax;
    std::vector<Expected> expected;
    data.count = 0;
    while (data.count < count) {
      const auto [o, d] = testing::RandomRoomRay(scene, rng);
      Hit hit;
      if (!scene.Intersect(o, d, hit, false)) continue;
      const vec3 n = FacingNormal(d, hit.normal);
      const Sample2 uv = Numbers(rng);
      const vec3 w = SampleCosineDirection(n, uv.u, uv.v);
      data.Stage(hit.point, hit.normal, n, uv);
      if (rng.Uniform() < 0.1) continue;  // staged, then dropped (roulette): overwritten
      data.Keep(0);
      expected.push_back({w, OffsetRayOrigin(hit.point, hit.normal, w)});
    }
    lanes.Sample(data);
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      const vec3 w(data.direction[0][j], data.direction[1][j], data.direction[2][j]);
      const vec3 start(data.start[0][j], data.start[1][j], data.start[2][j]);
      EXPECT_TRUE(SameBits(w, expected[j].direction) && SameBits(start, expected[j].start))
          << "normal " << data.facing[0][j] << " " << data.facing[1][j] << " " << data.facing[2][j]
          << ", u " << data.u[j] << ", v " << data.v[j];
      ++compared;
    }
  }
  return compared;
}

TEST(LambertianScatterLanes, EveryTargetSamplesScalarChildrenBitForBit) {
  const std::vector<Scene> scenes = {testing::CanonicalScene(),
                                     LoadScene(testing::SourcePath("scenes/cornell-mirror.json"))};
  for (const Scene& scene : scenes) {
    for (const SimdTarget target : SupportedSimdTargets()) {
      SCOPED_TRACE(SimdTargetName(target));
      EXPECT_GT(CompareWithScalar(scene, target, 3000), 10000);
    }
  }
}

}  // namespace
}  // namespace glint
