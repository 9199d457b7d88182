// CameraHitLanes: each camera ray's first hit found in SIMD lanes is Scene::Intersect's,
// to the bit (distance, point, normal, object, material), on every target this CPU runs,
// for rays through any point of the image, its edges and the image's centre lines
// (direction components exactly 0, which the lanes leave to Scene::Intersect).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/transport/CameraHitLanes.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::SameBits;

struct Counts {
  int compared = 0;
  int rare = 0;
  int objects = 0;  // first hits on a sphere, a cube or the light
};

Counts CompareWithScalar(const Scene& scene, SimdTarget target, int size, int groups) {
  const Pinhole camera = Camera::GeometryFor(scene.wall, scene.camera, size, size);
  const CameraHitLanes hitLanes(scene, camera, /*withAreaLight=*/true, target);
  Pcg32 rng(7, 11);
  Counts n;
  RayLanes lanes{};
  for (int g = 0; g < groups; ++g) {
    const int count = 1 + g % RayLanes::kMax;
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      // Mostly anywhere; now and then the image's edges or its centre lines.
      const int kind = static_cast<int>(rng.NextU32() % 8U);
      const double half = 0.5 * size;
      lanes.px[j] = kind == 0 ? half : (kind == 1 ? 0.0 : size * rng.Uniform());
      lanes.py[j] =
          kind == 2 ? half : (kind == 3 ? static_cast<double>(size) : size * rng.Uniform());
    }
    hitLanes.Trace(lanes, count);
    for (int i = 0; i < count; ++i) {
      const auto j = static_cast<std::size_t>(i);
      const vec3 d = camera.DirectionThrough(lanes.px[j], lanes.py[j]);
      EXPECT_TRUE(
          SameBits(d, vec3(lanes.direction[0][j], lanes.direction[1][j], lanes.direction[2][j])));
      Hit expected;
      const bool found = scene.Intersect(camera.Eye(), d, expected, /*withAreaLight=*/true);
      ++n.compared;
      if (lanes.closest[j] < 0.0) {
        ++n.rare;
        continue;
      }
      Hit got;
      EXPECT_EQ(hitLanes.FillHit(lanes, i, got), found)
          << "pixel point " << lanes.px[j] << ", " << lanes.py[j];
      EXPECT_TRUE(SameBits(got.t, expected.t)) << lanes.px[j] << ", " << lanes.py[j];
      EXPECT_TRUE(SameBits(got.point, expected.point));
      EXPECT_TRUE(SameBits(got.normal, expected.normal));
      EXPECT_EQ(got.object, expected.object) << lanes.px[j] << ", " << lanes.py[j];
      EXPECT_EQ(got.material, expected.material);
      EXPECT_EQ(got.light, expected.light);
      n.objects += expected.object >= scene.wall.ObjectOf(0) + Wall::kSides || expected.light;
    }
  }
  return n;
}

TEST(CameraHitLanes, EveryTargetFindsScalarFirstHitsBitForBit) {
  const std::vector<Scene> scenes = {
      testing::CanonicalScene(), LoadScene(testing::SourcePath("scenes/cornell-mirror.json")),
      // A sphere across the cube and one just below the light: near ties between objects.
      testing::CanonicalScene(
          {"/objects/0/center=[0.5,0.2,0.25]", "/objects/1/center=[0.5,0.83,0.5]"})};
  for (const Scene& scene : scenes) {
    for (const SimdTarget target : SupportedSimdTargets()) {
      SCOPED_TRACE(SimdTargetName(target));
      const Counts n = CompareWithScalar(scene, target, 64, 4000);
      EXPECT_GT(n.objects, n.compared / 20);  // objects and the light were met, not walls only
      EXPECT_GT(n.rare, 0);                   // the centre lines' rays were handed back
      EXPECT_LT(n.rare, n.compared / 2);      // a quarter of the points lie on the centre lines
    }
  }
}

// What the lanes leave to Scene::Intersect is rare where it matters: rays through random
// points of the image.
TEST(CameraHitLanes, LeavesFewRaysToTheScalarSearch) {
  const Scene scene = testing::CanonicalScene();
  const Pinhole camera = Camera::GeometryFor(scene.wall, scene.camera, 256, 256);
  const CameraHitLanes hitLanes(scene, camera, true, SimdTarget::Auto);
  Pcg32 rng(3, 5);
  RayLanes lanes{};
  int rare = 0;
  const int groups = 2000;
  for (int g = 0; g < groups; ++g) {
    for (std::size_t j = 0; j < RayLanes::kMax; ++j) {
      lanes.px[j] = 256.0 * rng.Uniform();
      lanes.py[j] = 256.0 * rng.Uniform();
    }
    hitLanes.Trace(lanes, RayLanes::kMax);
    for (std::size_t j = 0; j < RayLanes::kMax; ++j) rare += lanes.closest[j] < 0.0;
  }
  EXPECT_EQ(rare, 0);
}

}  // namespace
}  // namespace glint
