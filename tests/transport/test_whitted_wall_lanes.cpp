// WhittedWallLanes: the camera rays a pixel traces in SIMD lanes in Whitted mode give
// what the scalar WhittedIntegrator::Trace gives, to the bit, on every target this CPU
// runs: the image, the counters and every ray's node, shadow rays the shaft did not
// answer included.
#include <gtest/gtest.h>

#include <array>

#include "glint/camera/Camera.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

constexpr int kWidth = 33;
constexpr int kHeight = 17;
constexpr int kDepth = 10;

WhittedIntegrator WithLanes(const Scene& scene, SimdTarget target) {
  return {scene, kDepth, FresnelModel::Exact,
          Camera::GeometryFor(scene.wall, scene.camera, kWidth, kHeight), target};
}

TEST(WhittedWallLanes, EveryTargetRendersTheScalarImageBitForBit) {
  const Scene scene = testing::CanonicalScene();
  const WhittedIntegrator scalar(scene, kDepth);  // no camera: no lanes
  for (const SamplerKind sampler :
       {SamplerKind::Random, SamplerKind::Stratified, SamplerKind::Sobol}) {
    // 11 rays: a full block of 8 and one of 3, which leaves spare lanes on every target.
    const testing::LaneRender expected =
        testing::RenderWith(scene, scalar, sampler, 11, kWidth, kHeight);
    EXPECT_EQ(expected.stats.laneRays, 0U);
    for (const SimdTarget target : SupportedSimdTargets()) {
      SCOPED_TRACE(SimdTargetName(target));
      const WhittedIntegrator lanes = WithLanes(scene, target);
      const testing::LaneRender got =
          testing::RenderWith(scene, lanes, sampler, 11, kWidth, kHeight);
      EXPECT_EQ(testing::DifferingPixels(got.image, expected.image), 0);
      EXPECT_GT(got.stats.laneRays, got.stats.cameraRays / 6);
      EXPECT_EQ(got.stats.cameraRays, expected.stats.cameraRays);
      EXPECT_EQ(got.stats.shadowRays, expected.stats.shadowRays);
      EXPECT_EQ(got.stats.shadowRaysByShaft, expected.stats.shadowRaysByShaft);
      EXPECT_EQ(got.stats.TracedRays(), expected.stats.TracedRays());
    }
  }
}

// Every camera ray of a lanes pixel still owns its tree, and a pixel whose shaft cannot
// vouch for a point light casts that light's shadow rays as the scalar code does.
TEST(WhittedWallLanes, EachRayWritesTheScalarNodeOfItsOwnTree) {
  const Scene scene = testing::CanonicalScene();
  const WhittedIntegrator scalar(scene, kDepth);
  Camera camera(scene.wall, scene.camera, kWidth, kHeight);
  camera.PrepareShafts(scene, scalar.ShadowLights(), 1);
  int pixels = 0;
  int shadowed = 0;  // lanes pixels with a real shadow ray
  for (const SimdTarget target : SupportedSimdTargets()) {
    SCOPED_TRACE(SimdTargetName(target));
    const WhittedIntegrator lanes = WithLanes(scene, target);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const Pixel& pixel = camera.PixelAt(x, y);
        if (lanes.LaneWidth(pixel.Shaft()) == 0) continue;
        ++pixels;
        const auto index = static_cast<std::uint64_t>(y * kWidth + x);
        Sampler s1(SamplerKind::Sobol, 3, index, 0, 0, 13);
        Sampler s2(SamplerKind::Sobol, 3, index, 0, 0, 13);
        RayTree a;
        RayTree b;
        RenderStats st1;
        RenderStats st2;
        const PixelPass p1 = pixel.TracePass(camera, x, y, 13, scalar, s1, a, st1, true);
        const PixelPass p2 = pixel.TracePass(camera, x, y, 13, lanes, s2, b, st2, true);
        EXPECT_TRUE(testing::SameBits(p1.sum, p2.sum));
        EXPECT_EQ(st1.ShadowRaysTraced(), st2.ShadowRaysTraced());
        shadowed += st2.ShadowRaysTraced() > 0;
        ASSERT_EQ(a.Size(), 13U);
        testing::ExpectSameTrees(a, b);
      }
    }
  }
  EXPECT_GT(pixels, 100);
  EXPECT_GT(shadowed, 4);
}

// The lanes serve walls without a specular lobe and at most 4 point lights; elsewhere
// the pixel traces its rays one by one.
TEST(WhittedWallLanes, ServeOnlyWhatTheyCompute) {
  Scene scene = testing::CanonicalScene();
  Camera camera(scene.wall, scene.camera, kWidth, kHeight);
  const WhittedIntegrator lanes = WithLanes(scene, SimdTarget::Auto);
  camera.PrepareShafts(scene, lanes.ShadowLights(), 1);
  const Pixel* roomOnly = nullptr;
  for (int i = 0; i < kWidth * kHeight && roomOnly == nullptr; ++i) {
    const Pixel& p = camera.PixelAt(i % kWidth, i / kWidth);
    if (p.Shaft().roomOnly) roomOnly = &p;
  }
  ASSERT_NE(roomOnly, nullptr);
  EXPECT_GT(lanes.LaneWidth(roomOnly->Shaft()), 0);
  EXPECT_EQ(lanes.LaneWidth(PixelShaft{}), 0);

  Scene glossy = scene;
  std::array<Material, Wall::kSides> materials{};
  for (int side = 0; side < Wall::kSides; ++side) {
    materials[static_cast<std::size_t>(side)] = scene.wall.GetMaterial(side);
    materials[static_cast<std::size_t>(side)].whittedSpecular = 0.2;
  }
  glossy.wall = Wall(scene.wall.Position(), scene.wall.Size(), materials, scene.wall.ObjectOf(0));
  const WhittedIntegrator glossyLanes = WithLanes(glossy, SimdTarget::Auto);
  EXPECT_EQ(glossyLanes.LaneWidth(roomOnly->Shaft()), 0);

  Scene many = scene;
  while (many.pointLights.size() <= static_cast<std::size_t>(PointLightLanes::kMaxLights)) {
    many.pointLights.push_back(scene.pointLights.front());
  }
  const WhittedIntegrator manyLanes = WithLanes(many, SimdTarget::Auto);
  EXPECT_EQ(manyLanes.LaneWidth(roomOnly->Shaft()), 0);
}

}  // namespace
}  // namespace glint
