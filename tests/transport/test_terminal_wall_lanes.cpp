// TerminalWallLanes: the camera rays a pixel traces in SIMD lanes give what the scalar
// MonteCarloIntegrator::Trace gives, to the bit, on every target this CPU runs: the
// image, the counters and every ray's node.
#include <gtest/gtest.h>

#include "glint/camera/Camera.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

constexpr int kWidth = 33;
constexpr int kHeight = 17;

using testing::ExpectSameTrees;
using testing::LaneRender;
using testing::SameBits;

LaneRender Render(const Scene& scene, const Integrator& integrator, SamplerKind sampler, int spp) {
  return testing::RenderWith(scene, integrator, sampler, spp, kWidth, kHeight);
}

TEST(TerminalWallLanes, EveryTargetRendersTheScalarImageBitForBit) {
  const Scene scene = testing::CanonicalScene();
  const MonteCarloIntegrator scalar(scene, MonteCarloOptions{});  // no camera: no lanes
  for (const SamplerKind sampler :
       {SamplerKind::Random, SamplerKind::Stratified, SamplerKind::Sobol}) {
    // 11 rays: a full block of 8 and one of 3, which leaves spare lanes on every target.
    const LaneRender expected = Render(scene, scalar, sampler, 11);
    EXPECT_EQ(expected.stats.laneRays, 0U);
    for (const SimdTarget target : SupportedSimdTargets()) {
      SCOPED_TRACE(SimdTargetName(target));
      MonteCarloOptions o;
      o.simd = target;
      const MonteCarloIntegrator lanes(
          scene, o, Camera::GeometryFor(scene.wall, scene.camera, kWidth, kHeight));
      const LaneRender got = Render(scene, lanes, sampler, 11);
      EXPECT_EQ(testing::DifferingPixels(got.image, expected.image), 0);
      // A fifth of the camera rays ran in lanes at this size (the others' shafts hold objects), and
      // some of their shadow rays were traced (not all answered by the shaft): both halves of the
      // lanes' estimate were compared.
      EXPECT_GT(got.stats.laneRays, got.stats.cameraRays / 6);
      EXPECT_EQ(got.stats.cameraRays, expected.stats.cameraRays);
      EXPECT_EQ(got.stats.shadowRays, expected.stats.shadowRays);
      EXPECT_EQ(got.stats.shadowRaysByShaft, expected.stats.shadowRaysByShaft);
      EXPECT_EQ(got.stats.TracedRays(), expected.stats.TracedRays());
      EXPECT_GT(got.stats.ShadowRaysTraced(), 0U);
    }
  }
}

// Every camera ray of a lanes pixel still owns its tree: its node is the scalar one.
TEST(TerminalWallLanes, EachRayWritesTheScalarNodeOfItsOwnTree) {
  const Scene scene = testing::CanonicalScene();
  const MonteCarloIntegrator scalar(scene, MonteCarloOptions{});
  Camera camera(scene.wall, scene.camera, kWidth, kHeight);
  camera.PrepareShafts(scene, scalar.ShadowLights(), 1);
  int pixels = 0;
  for (const SimdTarget target : SupportedSimdTargets()) {
    SCOPED_TRACE(SimdTargetName(target));
    MonteCarloOptions o;
    o.simd = target;
    const MonteCarloIntegrator lanes(
        scene, o, Camera::GeometryFor(scene.wall, scene.camera, kWidth, kHeight));
    for (int y = 0; y < kHeight; y += 4) {
      for (int x = 0; x < kWidth; x += 4) {
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
        EXPECT_TRUE(SameBits(p1.sum, p2.sum));
        ASSERT_EQ(a.Size(), 13U);
        ExpectSameTrees(a, b);
      }
    }
  }
  EXPECT_GT(pixels, 10);
}

TEST(TerminalWallLanes, RefusesATargetTheCpuLacksNamingWhatItHas) {
  const Scene scene = testing::CanonicalScene();
  for (const SimdTarget target : {SimdTarget::Sse4, SimdTarget::Avx2, SimdTarget::Avx512}) {
    if (SimdTargetSupported(target)) continue;
    MonteCarloOptions o;
    o.simd = target;
    try {
      const MonteCarloIntegrator lanes(scene, o,
                                       Camera::GeometryFor(scene.wall, scene.camera, 8, 8));
      ADD_FAILURE() << "accepted " << SimdTargetName(target);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(SupportedSimdTargetNames()), std::string::npos);
    }
  }
  // Auto is the widest the CPU runs; scalar is always there.
  EXPECT_EQ(ResolveSimdTarget(SimdTarget::Auto), SupportedSimdTargets().back());
  EXPECT_EQ(SupportedSimdTargets().front(), SimdTarget::Scalar);
  EXPECT_EQ(ParseSimdTarget("avx2"), SimdTarget::Avx2);
  EXPECT_FALSE(ParseSimdTarget("avx3").has_value());
}

}  // namespace
}  // namespace glint
