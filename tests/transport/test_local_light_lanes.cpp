// LocalLightLanes: the Whitted local term at wall and object hits found in SIMD lanes is
// WhittedIntegrator::LocalLight's, to the bit, with as many shadow rays, on every target
// this CPU runs, for hits seen from random points of the room: lit, in the opaque
// objects' shadows (the spheres' and the cube's), behind a light, and at the room's edges.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/transport/LocalLightLanes.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::SameBits;

struct Counts {
  int compared = 0;
  int shadowed = 0;    // a light blocked by an object
  int objects = 0;     // hits on a sphere or a cube
  int highlights = 0;  // hits whose specular lobe adds light
  int dark = 0;        // no light reaches the hit
};

Counts CompareWithScalar(const Scene& scene, SimdTarget target, int groups) {
  const WhittedIntegrator whitted(scene, 10);
  // The same room without its objects: a hit whose term differs there is in a shadow.
  Scene open = scene;
  open.spheres.clear();
  open.cubes.clear();
  const WhittedIntegrator unshadowed(open, 10);
  const LocalLightLanes lanes(scene, target);
  Pcg32 rng(5, 17);
  Counts n;
  LocalLightLaneData data;
  for (int g = 0; g < groups; ++g) {
    const int count = 1 + g % RayLanes::kMax;
    std::vector<Colour> expected;
    std::vector<std::uint64_t> rays;
    for (int i = 0; i < count;) {
      const auto [o, d] = testing::RandomRoomRay(scene, rng);
      Hit hit;
      if (!scene.Intersect(o, d, hit, false) || !LocalLightLanes::Serves(*hit.material)) continue;
      if (hit.object < scene.wall.ObjectOf(0) + Wall::kSides && rng.Uniform() < 0.7) continue;
      RenderStats stats;
      expected.push_back(whitted.LocalLight(hit, d, stats));
      rays.push_back(stats.shadowRays);
      n.shadowed += !(unshadowed.LocalLight(hit, d, stats) == expected.back());
      const vec3 normal = FacingNormal(d, hit.normal);
      const auto j = static_cast<std::size_t>(i);
      for (std::size_t a = 0; a < 3; ++a) {
        const auto c = static_cast<glm::length_t>(a);
        data.point[a][j] = hit.point[c];
        data.normal[a][j] = normal[c];
        data.direction[a][j] = d[c];
      }
      LocalLightLanes::SetMaterial(data, j, *hit.material);
      n.objects += hit.object >= scene.wall.ObjectOf(0) + Wall::kSides;
      // Its material without the lobe (ks 0): a term that differs has a highlight.
      Material dull = *hit.material;
      dull.whittedSpecular = 0.0;
      Hit dullHit = hit;
      dullHit.material = &dull;
      n.highlights += !(whitted.LocalLight(dullHit, d, stats) == expected.back());
      ++i;
    }
    lanes.Shade(data, count);
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      const Colour got(data.colour[0][j], data.colour[1][j], data.colour[2][j]);
      EXPECT_TRUE(SameBits(got, expected[j]))
          << "point " << data.point[0][j] << " " << data.point[1][j] << " " << data.point[2][j];
      EXPECT_EQ(static_cast<std::uint64_t>(data.shadowRays[j]), rays[j]);
      ++n.compared;
      n.dark += got == Colour(0.0);
    }
  }
  return n;
}

TEST(LocalLightLanes, EveryTargetShadesScalarHitsBitForBit) {
  const std::vector<Scene> scenes = {
      testing::CanonicalScene(), LoadScene(testing::SourcePath("scenes/cornell-mirror.json")),
      // The spheres against the walls: shadow rays that graze them; other exponents.
      testing::CanonicalScene({"/objects/0/center=[0.2,0.2,0.2]", "/objects/1/center=[0.8,0.5,0.3]",
                               "/objects/0/exponent=7", "/objects/2/exponent=1024"}),
      testing::CanonicalScene({"/objects/0/exponent=1", "/objects/2/exponent=0"})};
  for (const Scene& scene : scenes) {
    for (const SimdTarget target : SupportedSimdTargets()) {
      SCOPED_TRACE(SimdTargetName(target));
      const Counts n = CompareWithScalar(scene, target, 3000);
      EXPECT_GT(n.shadowed, n.compared / 50);    // the objects' shadows were met
      EXPECT_GT(n.objects, n.compared / 4);      // and the objects, walls not only
      EXPECT_GT(n.highlights, n.compared / 50);  // with their highlights
      EXPECT_GT(n.dark, 0);                      // some hits see no light
      EXPECT_LT(n.dark, n.compared / 2);         // most see one
    }
  }
}

// The lanes raise a lobe by CosinePower's squarings: whole exponents in [0, 1024] only;
// any other lobe, and a hit with no lobe at all, goes to (or needs no) pow.
TEST(LocalLightLanes, ServeWholeExponentsUpTo1024) {
  Material m;
  m.whittedSpecular = 0.5;
  for (const double n : {0.0, 1.0, 100.0, 1023.0, 1024.0}) {
    m.exponent = n;
    EXPECT_TRUE(LocalLightLanes::Serves(m)) << n;
  }
  for (const double n : {0.5, 99.999, 1024.5, 1025.0, -1.0, -0.5, 1e300, std::nan("")}) {
    m.exponent = n;
    EXPECT_FALSE(LocalLightLanes::Serves(m)) << n;
  }
  m.whittedSpecular = 0.0;
  m.exponent = 0.5;
  EXPECT_TRUE(LocalLightLanes::Serves(m));  // no lobe
}

}  // namespace
}  // namespace glint
