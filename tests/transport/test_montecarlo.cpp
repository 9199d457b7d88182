// Monte Carlo mode, verified by statistics: analytic values, an albedo by quadrature,
// and agreement of independent estimators within their error bars.
#include <gtest/gtest.h>

#include <cstdio>

#include "glint/camera/Camera.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/Phong.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::BlockEstimates;
using testing::CanonicalScene;
using testing::MeanAndError;
using testing::PolygonCosineIntegral;
using testing::RenderBlocks;

// Radiance along one ray, estimated `n` times.
MeanAndError EstimateRadiance(const MonteCarloIntegrator& integrator, vec3 start, vec3 d, int n,
                              int channel, std::uint64_t seed) {
  RayTree tree;
  RenderStats stats;
  Sampler sampler(Pcg32(seed, 9));
  MeanAndError m;
  for (int i = 0; i < n; ++i) {
    tree.Clear();
    Ray ray;
    ray.start = start;
    ray.direction = glm::normalize(d);
    const std::uint32_t root = tree.Add(ray);
    m.Add(integrator.Trace(tree, root, PixelShaft{}, sampler, stats)[channel]);
  }
  return m;
}

TEST(MonteCarlo, UnoccludedWallRadianceMatchesLambertsFormula) {
  const Scene scene = CanonicalScene({"/objects=[]"});
  const MonteCarloIntegrator integrator(scene, {});
  const Rectangle& light = scene.light->Shape();
  const std::vector<vec3> corners = {light.PointFromUV(0, 0), light.PointFromUV(1, 0),
                                     light.PointFromUV(1, 1), light.PointFromUV(0, 1)};
  struct Case {
    vec3 point, normal, viewFrom;
    double rho;
    int channel;
  };
  const Case cases[] = {
      {vec3(0.3, 0.0, 0.6), vec3(0, 1, 0), vec3(0.3, 0.5, 0.6), 0.75, 0},    // floor
      {vec3(0.7, 0.3, 0.0), vec3(0, 0, 1), vec3(0.7, 0.3, 0.5), 0.75, 1},    // back wall
      {vec3(0.0, 0.8, 0.5), vec3(1, 0, 0), vec3(0.5, 0.8, 0.5), 0.75, 0},    // left wall, red
      {vec3(1.0, 0.95, 0.2), vec3(-1, 0, 0), vec3(0.5, 0.95, 0.2), 0.75, 1}  // right, grazing
  };
  std::uint64_t seed = 1;
  for (const Case& c : cases) {
    const double expected =
        c.rho * kInvPi * 50.0 * PolygonCosineIntegral(c.point, c.normal, corners);
    const MeanAndError m =
        EstimateRadiance(integrator, c.viewFrom, c.point - c.viewFrom, 200000, c.channel, seed++);
    // The test can see a 1% bias: three standard errors are well below 1%.
    ASSERT_LT(3.0 * m.StandardError(), 0.01 * expected);
    EXPECT_NEAR(m.mean, expected, 3.0 * m.StandardError())
        << "at (" << c.point.x << ", " << c.point.y << ", " << c.point.z << ")";
    std::printf(
        "wall point (%.2f, %.2f, %.2f): Monte Carlo %.6f +- %.6f, Lambert %.6f, "
        "deviation %+.2f standard errors (%+.4f%%)\n",
        c.point.x, c.point.y, c.point.z, m.mean, m.StandardError(), expected,
        (m.mean - expected) / m.StandardError(), 100.0 * (m.mean / expected - 1.0));
  }
}

TEST(MonteCarlo, LambertianObjectMatchesLambertsFormulaAndSpawnsNothingWithTerminalWalls) {
  // The top of O1, lambertian: rho / pi * Le * the cosine-weighted solid angle of the light.
  const Scene scene = LoadScene(testing::SourcePath("scenes/cornell-lambert.json"));
  const MonteCarloIntegrator integrator(scene, {});
  const Rectangle& light = scene.light->Shape();
  const std::vector<vec3> corners = {light.PointFromUV(0, 0), light.PointFromUV(1, 0),
                                     light.PointFromUV(1, 1), light.PointFromUV(0, 1)};
  const vec3 top(0.22, 0.36, 0.40);
  const double expected = 0.9 * kInvPi * 50.0 * PolygonCosineIntegral(top, vec3(0, 1, 0), corners);
  const MeanAndError m =
      EstimateRadiance(integrator, top + vec3(0, 0.1, 0), vec3(0, -1, 0), 200000, 0, 5);
  ASSERT_LT(3.0 * m.StandardError(), 0.01 * expected);
  EXPECT_NEAR(m.mean, expected, 3.0 * m.StandardError());
}

double PhongAlbedoByQuadrature(const Material& m, vec3 d, vec3 n) {
  // In the frame of the mirror direction R, alpha = (pi/2) s^2 crowds the nodes near the
  // lobe's axis; dw = sin(alpha) dalpha dphi.
  const Frame f = Frame::FromZ(Reflect(d, n));
  constexpr int kS = 3000;
  constexpr int kPhi = 720;
  double sum = 0.0;
  for (int i = 0; i < kS; ++i) {
    const double s = (i + 0.5) / kS;
    const double alpha = 0.5 * kPi * s * s;
    const double dAlpha = kPi * s / kS;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / kPhi;
      const vec3 psi = f.ToWorld(
          vec3(std::sin(alpha) * std::cos(phi), std::sin(alpha) * std::sin(phi), std::cos(alpha)));
      const double cosTheta = glm::dot(n, psi);
      if (cosTheta > 0.0) sum += PhongBrdf(m, d, n, psi).x * cosTheta * std::sin(alpha) * dAlpha;
    }
  }
  return sum * 2.0 * kPi / kPhi;
}

TEST(MonteCarlo, PhongAlbedoAgreesWithQuadratureAndNeverExceedsRho) {
  const vec3 n(0, 0, 1);
  Pcg32 rng(21, 4);
  for (double exponent : {1.0, 10.0, 100.0, 1000.0}) {
    for (double incidence : {0.0, 45.0, 80.0}) {
      Material m;
      m.type = MaterialType::Phong;
      m.reflectance = Colour(0.8);
      m.exponent = exponent;
      const double th = incidence * kPi / 180.0;
      const vec3 d(std::sin(th), 0.0, -std::cos(th));
      const double quadrature = PhongAlbedoByQuadrature(m, d, n);
      MeanAndError mc;
      for (int i = 0; i < 200000; ++i)
        mc.Add(SamplePhong(m, d, n, rng.Uniform(), rng.Uniform()).weight.x);
      const std::string what =
          "n = " + std::to_string(exponent) + ", " + std::to_string(incidence) + " deg";
      EXPECT_LE(quadrature, 0.8 * (1.0 + 1e-4)) << what;
      EXPECT_LE(mc.mean, 0.8 + 3.0 * mc.StandardError()) << what;
      EXPECT_NEAR(mc.mean, quadrature, 4.0 * mc.StandardError() + 1e-4 * quadrature) << what;
      if (incidence == 0.0) {
        EXPECT_NEAR(quadrature, 0.8, 2e-4) << what;  // exactly rho at normal incidence
      }
      if (exponent >= 10.0) {  // the comparison can see a 1% bias
        ASSERT_LT(4.0 * mc.StandardError(), 0.01 * quadrature) << what;
      }
    }
  }
}

// The normalised Phong lobe's n -> infinity limit is not the mirror: its albedo tends to
// rho cos(theta) (spec, "Objects"), while a mirror reflects rho at every angle. Wherever
// the whole lobe lies above the horizon the albedo is rho cos(theta) exactly, since
// (n + 2) / (2 pi) * integral of cos^n(alpha) psi dw = R and R.n = cos(theta); at grazing
// incidence the horizon cuts the lobe, and the gap closes as the lobe narrows.
TEST(MonteCarlo, PhongAlbedoApproachesRhoCosThetaAsTheExponentGrows) {
  const vec3 n(0, 0, 1);
  for (double incidence : {0.0, 30.0, 60.0, 80.0}) {
    const double th = incidence * kPi / 180.0;
    const vec3 d(std::sin(th), 0.0, -std::cos(th));
    const double limit = 0.8 * std::cos(th);
    double previous = INFINITY;
    for (double exponent : {1e2, 1e3, 1e4, 1e5}) {
      Material m;
      m.type = MaterialType::Phong;
      m.reflectance = Colour(0.8);
      m.exponent = exponent;
      const double gap = std::abs(PhongAlbedoByQuadrature(m, d, n) - limit);
      std::printf("Phong albedo, %2.0f deg, n = %6.0f: |albedo - rho cos| = %.3g\n", incidence,
                  exponent, gap);
      if (gap > 1e-9) {
        EXPECT_LT(gap, previous) << incidence << " deg, n = " << exponent;
      }
      if (exponent >= 1e3) {
        EXPECT_LT(gap, 1e-8) << incidence << " deg, n = " << exponent;
      }
      if (incidence == 80.0 && exponent == 1e2) {
        EXPECT_GT(gap, 1e-4);  // the horizon cuts the lobe at grazing incidence
      }
      previous = gap;
    }
    // Far from rho away from normal incidence: this is not the mirror.
    if (incidence > 0.0) {
      EXPECT_GT(std::abs(0.8 - limit), 0.1) << incidence << " deg";
    }
  }
}

TEST(MonteCarlo, TerminalCeilingIsBlackTheLightIsLeAndDiffuseWallsLightTheCeiling) {
  const Scene scene = CanonicalScene();
  const MonteCarloIntegrator terminal(scene, {});
  MonteCarloOptions diffuseOptions;
  diffuseOptions.walls = MonteCarloOptions::Walls::Diffuse;
  const MonteCarloIntegrator diffuse(scene, diffuseOptions);
  const vec3 eye(0.5, 0.5, 2.5);
  const vec3 ceiling(0.2, 1.0, 0.3);
  EXPECT_EQ(EstimateRadiance(terminal, eye, ceiling - eye, 1000, 0, 1).mean, 0.0);
  EXPECT_GT(EstimateRadiance(diffuse, eye, ceiling - eye, 1000, 0, 1).mean, 0.01);
  const MeanAndError le = EstimateRadiance(terminal, eye, vec3(0.5, 1.0, 0.5) - eye, 10, 1, 1);
  EXPECT_EQ(le.mean, 50.0);
  EXPECT_EQ(le.StandardError(), 0.0);
}

TEST(MonteCarlo, LightBrdfAndMisSamplingAgreeBlockByBlock) {
  // O1 and O3 with a low exponent, where light sampling and BRDF sampling both matter.
  const Scene scene = CanonicalScene({"/objects/0/exponent=5", "/objects/2/exponent=20"});
  using S = MonteCarloOptions::Strategy;
  MonteCarloOptions o;
  o.strategy = S::Mis;
  const BlockEstimates mis = RenderBlocks(scene, o, 32, 8, 32, 8, 100);
  o.strategy = S::Light;
  const BlockEstimates light = RenderBlocks(scene, o, 32, 8, 32, 8, 200);
  o.strategy = S::Brdf;
  const BlockEstimates brdf = RenderBlocks(scene, o, 32, 8, 32, 8, 300);
  o.strategy = S::Mis;
  o.branches = 3;
  const BlockEstimates branched = RenderBlocks(scene, o, 32, 8, 12, 8, 400);
  // |z| bound for 4 x 48 comparisons at family level 0.01 (Sidak): about 4.0.
  const double zMax = 4.0;
  const std::pair<const BlockEstimates*, const char*> others[] = {
      {&light, "light"}, {&brdf, "brdf"}, {&branched, "mis, 3 branches"}};
  for (const auto& [other, name] : others) {
    for (std::size_t i = 0; i < mis.blocks.size(); ++i) {
      const MeanAndError& a = mis.blocks[i];
      const MeanAndError& b = other->blocks[i];
      const double se =
          std::sqrt(a.StandardError() * a.StandardError() + b.StandardError() * b.StandardError());
      EXPECT_LE(std::abs(a.mean - b.mean), zMax * se + 1e-12)
          << name << " block " << i / 3 << " channel " << i % 3 << ": " << a.mean << " vs "
          << b.mean;
    }
  }
}

TEST(MonteCarlo, GlassSplitAndChooseAgree) {
  const Scene scene = CanonicalScene();
  MonteCarloOptions o;
  const BlockEstimates split = RenderBlocks(scene, o, 32, 8, 32, 8, 500);
  o.glass = MonteCarloOptions::Glass::Choose;
  const BlockEstimates choose = RenderBlocks(scene, o, 32, 8, 32, 8, 600);
  for (std::size_t i = 0; i < split.blocks.size(); ++i) {
    const double se = std::hypot(split.blocks[i].StandardError(), choose.blocks[i].StandardError());
    EXPECT_LE(std::abs(split.blocks[i].mean - choose.blocks[i].mean), 4.0 * se + 1e-12)
        << "block " << i / 3 << " channel " << i % 3;
  }
}

TEST(MonteCarlo, NoNonFiniteSamplesInAnyMode) {
  const Scene scene = CanonicalScene();
  using O = MonteCarloOptions;
  for (O::Walls walls : {O::Walls::Terminal, O::Walls::Diffuse}) {
    for (O::Strategy strategy : {O::Strategy::Mis, O::Strategy::Light, O::Strategy::Brdf}) {
      for (O::Glass glass : {O::Glass::Split, O::Glass::Choose}) {
        O o;
        o.walls = walls;
        o.strategy = strategy;
        o.glass = glass;
        o.fresnel = glass == O::Glass::Split ? O::Fresnel::Exact : O::Fresnel::SmallAngle;
        o.branches = strategy == O::Strategy::Mis ? 2 : 1;
        const MonteCarloIntegrator integrator(scene, o);
        Camera camera(scene.wall, scene.camera.eye, 24, 24);
        RenderOptions ro;
        ro.raysPerPixel = 4;
        const RenderStats stats = camera.Render(integrator, ro);
        EXPECT_EQ(stats.nonFiniteSamples, 0u);
        const Image image = camera.ToImage();
        for (const Colour& c : image.Pixels()) ASSERT_TRUE(IsFinite(c));
      }
    }
  }
}

}  // namespace
}  // namespace glint
