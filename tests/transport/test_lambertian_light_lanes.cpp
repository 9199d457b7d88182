// LambertianLightLanes: the next-event estimate at Lambertian hits found in SIMD lanes is
// MonteCarloIntegrator::DirectLight's, to the bit, with the same shadow rays counted, on
// every target this CPU runs, for wall hits seen from random points of the room: lit, in
// the shadows of the opaque objects and of the glass (which blocks Monte Carlo's shadow
// rays), facing away from the light, and with the shadow test answered by a shaft.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/transport/LambertianLightLanes.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::SameBits;

struct Counts {
  int compared = 0;
  int shadowed = 0;  // the light blocked by an object
  int dark = 0;      // no light reaches the hit
  int untested = 0;  // the shadow test answered in advance
};

Counts CompareWithScalar(const Scene& scene, SimdTarget target, int groups) {
  MonteCarloOptions options;
  options.walls = MonteCarloOptions::Walls::Diffuse;
  const MonteCarloIntegrator mc(scene, options);
  Scene open = scene;  // without its objects: an estimate that differs there is in a shadow
  open.spheres.clear();
  open.cubes.clear();
  const MonteCarloIntegrator unshadowed(open, options);
  const LambertianLightLanes lanes(scene, *scene.light, target);
  Pcg32 rng(7, 3);
  Counts n;
  LambertianLightLaneData data;
  for (int g = 0; g < groups; ++g) {
    const int count = 1 + g % RayLanes::kMax;
    std::vector<Colour> expected;
    std::vector<std::uint64_t> rays;
    std::vector<std::uint64_t> byShaft;
    data.count = 0;
    while (data.count < count) {
      const auto [o, d] = testing::RandomRoomRay(scene, rng);
      Hit hit;
      if (!scene.Intersect(o, d, hit, false) || hit.material->type != MaterialType::Lambertian) {
        continue;
      }
      const vec3 normal = FacingNormal(d, hit.normal);
      const Sample2 uv{rng.Uniform(), rng.Uniform()};
      const bool unoccluded = rng.Uniform() < 0.1;
      RenderStats stats;
      expected.push_back(mc.DirectLight(hit, d, normal, 0.0, uv, stats, unoccluded));
      rays.push_back(stats.shadowRays);
      byShaft.push_back(stats.shadowRaysByShaft);
      n.shadowed += !unoccluded &&
                    !(unshadowed.DirectLight(hit, d, normal, 0.0, uv, stats) == expected.back());
      n.untested += unoccluded;
      data.Add(0, hit.point, normal, scene.light->Radiance() * hit.material->reflectance, uv,
               unoccluded);
    }
    lanes.Estimate(data);
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      const Colour got(data.colour[0][j], data.colour[1][j], data.colour[2][j]);
      EXPECT_TRUE(SameBits(got, expected[j]))
          << "point " << data.point[0][j] << " " << data.point[1][j] << " " << data.point[2][j];
      EXPECT_EQ(data.cast[j] != 0.0 ? 1U : 0U, rays[j]);
      EXPECT_EQ(data.cast[j] != 0.0 && data.unoccluded[j] != 0.0 ? 1U : 0U, byShaft[j]);
      ++n.compared;
      n.dark += got == Colour(0.0);
    }
  }
  return n;
}

TEST(LambertianLightLanes, EveryTargetEstimatesScalarHitsBitForBit) {
  const std::vector<Scene> scenes = {
      testing::CanonicalScene(), LoadScene(testing::SourcePath("scenes/cornell-mirror.json")),
      // The spheres against the walls and under the light: shadow segments that graze them.
      testing::CanonicalScene(
          {"/objects/0/center=[0.2,0.2,0.2]", "/objects/1/center=[0.8,0.5,0.3]"})};
  for (const Scene& scene : scenes) {
    for (const SimdTarget target : SupportedSimdTargets()) {
      SCOPED_TRACE(SimdTargetName(target));
      const Counts n = CompareWithScalar(scene, target, 3000);
      EXPECT_GT(n.shadowed, n.compared / 50);  // the objects' shadows were met
      EXPECT_GT(n.untested, n.compared / 20);  // and shadow tests answered in advance
      EXPECT_GT(n.dark, n.compared / 50);      // some hits see no light
      EXPECT_LT(n.dark, n.compared / 2);       // most see it
    }
  }
}

}  // namespace
}  // namespace glint
