#include <gtest/gtest.h>

#include "glint/sampling/Rng.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::CanonicalScene;

TEST(Scene, LightWinsOverTheCoplanarCeiling) {
  const Scene scene = CanonicalScene();
  ASSERT_TRUE(scene.light.has_value());
  Pcg32 rng(11, 0);
  for (int i = 0; i < 20000; ++i) {
    // From anywhere in the room to anywhere on the light, edges included.
    const vec3 origin(0.05 + 0.9 * rng.Uniform(), 0.3 + 0.6 * rng.Uniform(),
                      0.05 + 0.9 * rng.Uniform());
    const double u = i < 100 ? (i % 2) : rng.Uniform();
    const double v = i < 100 ? ((i / 2) % 2) : rng.Uniform();
    const vec3 target = scene.light->SamplePoint(u, v);
    const vec3 d = glm::normalize(target - origin);
    Hit hit;
    if (!scene.Intersect(origin, d, hit, true)) FAIL() << "escaped the room";
    if (hit.object <= 4) {
      ASSERT_EQ(hit.object, 1) << "only the ceiling may tie with the light";
      // Only at the light's very boundary may round-off give the ceiling.
      ASSERT_TRUE(u == 0.0 || u == 1.0 || v == 0.0 || v == 1.0) << u << " " << v;
      continue;
    }
    if (hit.object != scene.light->Object()) continue;  // an object stood in the way
    ASSERT_TRUE(hit.light);
    ASSERT_NEAR(glm::length(hit.point - target), 0.0, 1e-12);
  }
}

TEST(Scene, CeilingOutsideTheLightAndWhittedModeSeeNoLight) {
  const Scene scene = CanonicalScene();
  Hit hit;
  ASSERT_TRUE(scene.Intersect(vec3(0.3, 0.5, 0.5), vec3(0, 1, 0), hit, true));
  EXPECT_FALSE(hit.light);
  EXPECT_EQ(scene.ObjectName(hit.object), "W2");
  ASSERT_TRUE(scene.Intersect(vec3(0.5, 0.5, 0.5), vec3(0, 1, 0), hit, true));
  EXPECT_TRUE(hit.light);
  EXPECT_DOUBLE_EQ(hit.point.y, 1.0);
  EXPECT_EQ(hit.normal, vec3(0, -1, 0));
  ASSERT_TRUE(scene.Intersect(vec3(0.5, 0.5, 0.5), vec3(0, 1, 0), hit, false));
  EXPECT_FALSE(hit.light);
  EXPECT_EQ(scene.ObjectName(hit.object), "W2");
}

TEST(Scene, ClosestHitAmongWallsAndObjects) {
  const Scene scene = CanonicalScene();
  Hit hit;
  // Straight down onto the top of O1 (the mirror sphere).
  ASSERT_TRUE(scene.Intersect(vec3(0.22, 0.9, 0.40), vec3(0, -1, 0), hit, false));
  EXPECT_EQ(scene.ObjectName(hit.object), "O1");
  EXPECT_NEAR(hit.point.y, 0.36, 1e-12);
  // Straight down onto the cube's top.
  ASSERT_TRUE(scene.Intersect(vec3(0.5, 0.9, 0.2), vec3(0, -1, 0), hit, false));
  EXPECT_EQ(scene.ObjectName(hit.object), "O3");
  EXPECT_NEAR(hit.point.y, 0.28, 1e-12);
  // Out through the open front: nothing.
  EXPECT_FALSE(scene.Intersect(vec3(0.5, 0.5, 0.5), vec3(0, 0, 1), hit, true));
}

TEST(Scene, WhittedShadowRaysPassTransparentObjectsOnly) {
  const Scene scene = CanonicalScene();
  // Through the glass sphere O2: visible.
  EXPECT_TRUE(scene.VisibleThroughTransparent(vec3(0.74, 0.5, 0.70), vec3(0.74, 0.001, 0.70)));
  // Through the mirror sphere O1 and the cube O3: blocked.
  EXPECT_FALSE(scene.VisibleThroughTransparent(vec3(0.22, 0.5, 0.40), vec3(0.22, 0.001, 0.40)));
  EXPECT_FALSE(scene.VisibleThroughTransparent(vec3(0.5, 0.5, 0.2), vec3(0.5, 0.001, 0.2)));
  // Beside them: visible.
  EXPECT_TRUE(scene.VisibleThroughTransparent(vec3(0.5, 0.5, 0.8), vec3(0.5, 0.001, 0.8)));
}

}  // namespace
}  // namespace glint
