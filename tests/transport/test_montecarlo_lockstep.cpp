// MonteCarloIntegrator::TraceGroupFromLanes: the paths of up to 64 camera rays in
// lock-step, each still depth first, their secondary rays' hits found in SIMD lanes,
// give what the depth-first recursion gives, to the bit: the image and every counter,
// on every target this CPU runs, for each switch the group path takes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

constexpr int kWidth = 33;
constexpr int kHeight = 17;

struct Case {
  std::string name;
  MonteCarloOptions options;
};

std::vector<Case> Cases() {
  std::vector<Case> cases;
  MonteCarloOptions o;
  cases.push_back({"terminal walls", o});
  o.walls = MonteCarloOptions::Walls::Diffuse;
  cases.push_back({"diffuse walls", o});
  MonteCarloOptions choose = o;
  choose.glass = MonteCarloOptions::Glass::Choose;
  cases.push_back({"diffuse walls, glass choose", choose});
  MonteCarloOptions two = o;
  two.branches = 2;
  cases.push_back({"diffuse walls, 2 branches", two});
  MonteCarloOptions caustics = o;
  caustics.caustics = MonteCarloOptions::Caustics::Light;
  cases.push_back({"diffuse walls, caustics by light tracing", caustics});
  MonteCarloOptions brdf = o;
  brdf.mirrorLight = MonteCarloOptions::MirrorLight::Brdf;
  brdf.strategy = MonteCarloOptions::Strategy::Brdf;
  cases.push_back({"diffuse walls, BRDF sampling only", brdf});
  return cases;
}

TEST(MonteCarloLockStep, EveryTargetRendersTheDepthFirstImageBitForBit) {
  for (const Scene& scene :
       {testing::CanonicalScene(), LoadScene(testing::SourcePath("scenes/cornell-mirror.json"))}) {
    for (const Case& c : Cases()) {
      SCOPED_TRACE(c.name);
      const auto camera = Camera::GeometryFor(scene.wall, scene.camera, kWidth, kHeight);
      MonteCarloOptions scalarOptions = c.options;
      scalarOptions.simd = SimdTarget::Scalar;  // the first-hit lanes need 4: depth first
      const MonteCarloIntegrator scalar(scene, scalarOptions, camera);
      ASSERT_FALSE(scalar.FirstHitLanes(PixelShaft{}, 70));
      // 70 rays: a group of 64, whose slots take new paths as theirs end, and one of 6.
      const testing::LaneRender expected =
          testing::RenderWith(scene, scalar, SamplerKind::Sobol, 70, kWidth, kHeight);
      for (const SimdTarget target : SupportedSimdTargets()) {
        MonteCarloOptions o = c.options;
        o.simd = target;
        const MonteCarloIntegrator lanes(scene, o, camera);
        if (!lanes.FirstHitLanes(PixelShaft{}, 70)) continue;  // fewer than 4 lanes
        SCOPED_TRACE(SimdTargetName(target));
        ASSERT_TRUE(lanes.TracesGroupsFromLanes());
        const testing::LaneRender got =
            testing::RenderWith(scene, lanes, SamplerKind::Sobol, 70, kWidth, kHeight);
        EXPECT_EQ(testing::DifferingPixels(got.image, expected.image), 0);
        EXPECT_EQ(got.stats.ToCounters()[0], expected.stats.ToCounters()[0]);
        for (std::size_t k = 1; k < 9; ++k) {  // every counter but the lanes' own
          EXPECT_EQ(got.stats.ToCounters()[k], expected.stats.ToCounters()[k]) << "counter " << k;
        }
        EXPECT_GT(got.stats.laneRays, 0U);
      }
    }
  }
}

// Three children a node or more: the stack's bound does not hold, the paths run depth
// first as before.
TEST(MonteCarloLockStep, ThreeBranchesTraceDepthFirst) {
  const Scene scene = testing::CanonicalScene();
  MonteCarloOptions o;
  o.branches = 3;
  const MonteCarloIntegrator mc(scene, o,
                                Camera::GeometryFor(scene.wall, scene.camera, kWidth, kHeight));
  EXPECT_FALSE(mc.TracesGroupsFromLanes());
}

}  // namespace
}  // namespace glint
