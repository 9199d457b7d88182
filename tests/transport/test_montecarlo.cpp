// Monte Carlo mode, verified by statistics: analytic values, an albedo by quadrature,
// and agreement of independent estimators within their error bars.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "glint/camera/Camera.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/Phong.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Power.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::BlockEstimates;
using testing::CanonicalScene;
using testing::ExpectBlocksAgreeWithPower;
using testing::MeanAndError;
using testing::PolygonCosineIntegral;
using testing::RenderBlocks;

// Radiance along one ray, estimated `n` times, every channel.
std::array<MeanAndError, 3> EstimateRadianceColour(const MonteCarloIntegrator& integrator,
                                                   vec3 start, vec3 d, int n, std::uint64_t seed) {
  RayTree tree;
  RenderStats stats;
  Sampler sampler(Pcg32(seed, 9));
  std::array<MeanAndError, 3> m;
  for (int i = 0; i < n; ++i) {
    tree.Clear();
    Ray ray;
    ray.start = start;
    ray.direction = glm::normalize(d);
    const std::uint32_t root = tree.Add(ray);
    const Colour c = integrator.Trace(tree, root, PixelShaft{}, sampler, stats);
    for (int k = 0; k < 3; ++k) m[static_cast<std::size_t>(k)].Add(c[k]);
  }
  return m;
}

// One channel of it.
MeanAndError EstimateRadiance(const MonteCarloIntegrator& integrator, vec3 start, vec3 d, int n,
                              int channel, std::uint64_t seed) {
  return EstimateRadianceColour(integrator, start, d, n, seed)[static_cast<std::size_t>(channel)];
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
    // Within three standard errors of Lambert's value, and able to see a 1% bias.
    testing::ExpectNearWithPower(m.mean, m.StandardError(), expected,
                                 "wall point (" + std::to_string(c.point.x) + ", " +
                                     std::to_string(c.point.y) + ", " + std::to_string(c.point.z) +
                                     ")");
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
  testing::ExpectNearWithPower(m.mean, m.StandardError(), expected, "the top of O1");
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
      for (int i = 0; i < 400000; ++i)
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
        testing::ExpectNearWithPower(mc.mean, mc.StandardError(), quadrature, what, 4.0);
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

TEST(Statistics, StudentTQuantilesMatchTheTables) {
  // Two-sided quantiles from the tables (e.g. Abramowitz and Stegun 26.10).
  EXPECT_NEAR(testing::StudentTQuantileTwoSided(0.05, 10.0), 2.2281, 1e-4);
  EXPECT_NEAR(testing::StudentTQuantileTwoSided(0.01, 14.0), 2.9768, 1e-4);
  EXPECT_NEAR(testing::StudentTQuantileTwoSided(0.001, 5.0), 6.8688, 1e-4);
  EXPECT_NEAR(testing::StudentTQuantileTwoSided(0.05, 1e6), 1.9600, 1e-4);
}

// The block tests: 32 runs a side (Welch's t with about 62 degrees of freedom, against
// Student's quantiles at family level 0.01 over 4 x 4 blocks x 3 channels, and each
// channel's weighted whole-image mean), each showing it would see a 1% bias.
constexpr int kSize = 32;
constexpr int kBlock = 8;
constexpr int kRuns = 32;

TEST(MonteCarlo, LightBrdfAndMisSamplingAgreeBlockByBlock) {
  // O1 and O3 with a low exponent, where light sampling and BRDF sampling both matter.
  const Scene scene = CanonicalScene({"/objects/0/exponent=5", "/objects/2/exponent=20"});
  const MonteCarloIntegrator pilotIntegrator(scene, {});
  const Image pilot =
      testing::RenderWithSampler(scene, pilotIntegrator, SamplerKind::Random, kSize, 16, 99);
  using S = MonteCarloOptions::Strategy;
  for (const SamplerKind sampler : {SamplerKind::Sobol, SamplerKind::Random}) {
    const std::string name = SamplerName(sampler);
    MonteCarloOptions o;
    o.strategy = S::Mis;
    const BlockEstimates mis =
        RenderBlocks(scene, o, kSize, kBlock, 64, kRuns, 100, pilot, sampler);
    o.strategy = S::Light;
    const BlockEstimates light =
        RenderBlocks(scene, o, kSize, kBlock, 64, kRuns, 200, pilot, sampler);
    // BRDF sampling alone finds the light through O1's wide lobe rarely and brightly: a
    // heavy tail, whose mean over few rays reads low (by 0.3% in the block of O1's
    // highlight at 32 runs of 64 rays, t of 6). More rays keep it within t.
    o.strategy = S::Brdf;
    const BlockEstimates brdf =
        RenderBlocks(scene, o, kSize, kBlock, 256, kRuns, 300, pilot, sampler);
    o.strategy = S::Mis;
    o.branches = 3;
    const BlockEstimates branched =
        RenderBlocks(scene, o, kSize, kBlock, 24, kRuns, 400, pilot, sampler);
    ExpectBlocksAgreeWithPower(name + ": mis against light", mis, light);
    ExpectBlocksAgreeWithPower(name + ": mis against brdf", mis, brdf);
    ExpectBlocksAgreeWithPower(name + ": mis against mis, 3 branches", mis, branched);
  }
}

TEST(MonteCarlo, GlassSplitAndChooseAgree) {
  const Scene scene = CanonicalScene();
  const MonteCarloIntegrator pilotIntegrator(scene, {});
  const Image pilot =
      testing::RenderWithSampler(scene, pilotIntegrator, SamplerKind::Random, kSize, 16, 99);
  for (const SamplerKind sampler : {SamplerKind::Sobol, SamplerKind::Random}) {
    MonteCarloOptions o;
    const BlockEstimates split =
        RenderBlocks(scene, o, kSize, kBlock, 64, kRuns, 500, pilot, sampler);
    o.glass = MonteCarloOptions::Glass::Choose;
    const BlockEstimates choose =
        RenderBlocks(scene, o, kSize, kBlock, 64, kRuns, 600, pilot, sampler);
    ExpectBlocksAgreeWithPower(std::string(SamplerName(sampler)) + ": glass split against choose",
                               split, choose);
  }
}

// The radiance a Phong object sends toward the eye, against an estimate that shares
// neither its light sampling, its lobe sampling nor its MIS weights: the light's part by
// quadrature over the light rectangle (a 256 x 256 grid of points, each tested for
// shadow), the rest by cosine-distributed rays whose incoming radiance is the
// integrator's own for a ray leaving the point (the light itself counted zero there).
// Each strategy (light, brdf, mis, mis with 3 branches) at a point of O1's highlight
// (exponent 5), and of O3 (exponent 5) where no light arrives directly and the lobe's
// rays bring everything, must agree, with the power to see a 1% bias.
struct PhongCase {
  const char* name;
  vec3 p, n;
  const Material* m;
  int restRays;   // for the part of the light that does not come straight from the light
  bool brdfOnly;  // test the BRDF-only strategy here too
};

void ExpectPhongRadianceAgrees(const Scene& scene, const PhongCase& c, std::uint64_t seed) {
  const vec3 eye = scene.camera.eye;
  const Light& light = *scene.light;
  const vec3 d = glm::normalize(c.p - eye);
  Hit first;
  ASSERT_TRUE(scene.Intersect(eye, d, first, true));
  ASSERT_LT(glm::length(first.point - c.p), 1e-6) << c.name << ": the eye does not see it";
  // The light's part, by quadrature (midpoints of a 256 x 256 grid).
  constexpr int kGrid = 256;
  Colour direct(0.0);
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const vec3 y = light.Shape().PointFromUV((i + 0.5) / kGrid, (j + 0.5) / kGrid);
      const vec3 w = y - c.p;
      const double r2 = glm::dot(w, w);
      const vec3 wi = w / std::sqrt(r2);
      const double cosP = glm::dot(c.n, wi);
      const double cosL = -glm::dot(light.Normal(), wi);
      if (cosP <= 0.0 || cosL <= 0.0 || scene.Occluded(OffsetRayOrigin(c.p, c.n, wi), y)) continue;
      direct += PhongBrdf(*c.m, d, c.n, wi) * light.Radiance() *
                (cosP * cosL / r2 * light.Area() / (kGrid * kGrid));
    }
  }
  // The rest: f cos L_in / pdf, L_in traced by the integrator (the light itself counted
  // zero: it is the quadrature's), directions from a defensive mixture of its own: with
  // probability 0.9 uniform in the cone around the mirror direction R where the lobe
  // cos^n is above 1e-6 of its peak, with 0.1 cosine-distributed over the hemisphere.
  const vec3 mirror = Reflect(d, c.n);
  const double cosCone = std::min(std::pow(1e-6, 1.0 / std::max(c.m->exponent, 1e-3)), 0.999);
  const double cone = 2.0 * kPi * (1.0 - cosCone);
  const Frame around = Frame::FromZ(mirror);
  const Frame frame = Frame::FromZ(c.n);
  const MonteCarloIntegrator reference(scene, {});
  Pcg32 rng(seed, 11);
  Sampler sampler(Pcg32(seed, 12));
  RayTree tree;
  RenderStats stats;
  MeanAndError indirect[3];
  for (int i = 0; i < c.restRays; ++i) {
    vec3 wi;
    const double u = rng.Uniform();
    const double v = rng.Uniform();
    if (rng.Uniform() < 0.9) {
      const double cosT = 1.0 - u * (1.0 - cosCone);
      const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
      wi = around.ToWorld(
          vec3(sinT * std::cos(2.0 * kPi * v), sinT * std::sin(2.0 * kPi * v), cosT));
    } else {
      wi = frame.ToWorld(SampleCosineHemisphere(u, v));
    }
    const double cosP = glm::dot(c.n, wi);
    Colour e(0.0);
    Hit hit;
    if (cosP > 0.0 && scene.Intersect(OffsetRayOrigin(c.p, c.n, wi), wi, hit, true) && !hit.light) {
      const double pdf = (glm::dot(wi, mirror) >= cosCone ? 0.9 / cone : 0.0) + 0.1 * cosP * kInvPi;
      tree.Clear();
      Ray ray;
      ray.start = OffsetRayOrigin(c.p, c.n, wi);
      ray.direction = wi;
      const std::uint32_t root = tree.Add(ray);
      e = PhongBrdf(*c.m, d, c.n, wi) * (cosP / pdf) *
          reference.Trace(tree, root, PixelShaft{}, sampler, stats);
    }
    for (int k = 0; k < 3; ++k) indirect[k].Add(e[k]);
  }
  using S = MonteCarloOptions::Strategy;
  const std::pair<S, int> strategies[] = {{S::Light, 1}, {S::Brdf, 1}, {S::Mis, 1}, {S::Mis, 3}};
  for (const auto& [strategy, branches] : strategies) {
    if (strategy == S::Brdf && !c.brdfOnly) continue;
    MonteCarloOptions o;
    o.strategy = strategy;
    o.branches = branches;
    const MonteCarloIntegrator integrator(scene, o);
    const std::string label = std::string(c.name) + ", strategy " +
                              (strategy == S::Light  ? "light"
                               : strategy == S::Brdf ? "brdf"
                                                     : "mis") +
                              ", " + std::to_string(branches) + " branch(es)";
    const std::array<MeanAndError, 3> all = EstimateRadianceColour(
        integrator, eye, d, 2000000,
        seed + 100 + static_cast<int>(strategy) * 10 + static_cast<std::uint64_t>(branches));
    for (int k = 0; k < 3; ++k) {
      const MeanAndError& m = all[static_cast<std::size_t>(k)];
      const double exact = direct[k] + indirect[k].mean;
      const double se = std::hypot(m.StandardError(), indirect[k].StandardError());
      std::printf(
          "%s, channel %d: %.6f +- %.6f against %.6f (light %.6f + rest %.6f +- %.6f): "
          "%+.2f sigma, a 1%% bias is %.1f sigma\n",
          label.c_str(), k, m.mean, m.StandardError(), exact, direct[k], indirect[k].mean,
          indirect[k].StandardError(), (m.mean - exact) / se, 0.01 * exact / se);
      testing::ExpectNearWithPower(m.mean, se, exact, label + ", channel " + std::to_string(k),
                                   4.0);
    }
  }
}

// The point of a sphere where the eye sees the light's centre reflected (a search).
vec3 HighlightNormal(const Scene& scene, const Sphere& s) {
  const vec3 eye = scene.camera.eye;
  const vec3 target = scene.light->Shape().PointFromUV(0.5, 0.5);
  vec3 best(0.0, 1.0, 0.0);
  double bestDot = -2.0;
  for (int i = 0; i <= 400; ++i) {
    for (int j = 0; j < 800; ++j) {
      const double theta = kPi * i / 400.0;
      const double phi = 2.0 * kPi * j / 800.0;
      const vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                   std::sin(theta) * std::sin(phi));
      const vec3 p = s.Centre() + s.Radius() * n;
      const vec3 d = glm::normalize(p - eye);
      if (glm::dot(d, n) >= 0.0) continue;
      const double k = glm::dot(Reflect(d, n), glm::normalize(target - p));
      if (k > bestDot) {
        bestDot = k;
        best = n;
      }
    }
  }
  return best;
}

// The radiance a Phong object sends toward the eye, against an estimate that shares
// neither its light sampling, its lobe sampling nor its MIS weights: the light's part by
// quadrature over the light rectangle (a 256 x 256 grid of points, each tested for
// shadow), the rest by rays of a mixture of its own whose incoming radiance is the
// integrator's own for a ray leaving the point. Each strategy (light, brdf, mis, mis with
// 3 branches) must agree, with the power to see a 1% bias, at a point of O1 (exponent 5)
// lit by the light, at O3's top (exponent 5) where no light arrives directly and the
// lobe's rays bring everything, and at O1's highlight with exponent 1000, where BRDF
// sampling finds the light and MIS weighs mostly its rays.
TEST(MonteCarlo, PhongRadianceAgreesWithQuadratureOfTheLightInEveryStrategy) {
  const Scene scene = CanonicalScene({"/objects/0/exponent=5", "/objects/2/exponent=5"});
  const vec3 eye = scene.camera.eye;
  const Sphere& o1 = scene.spheres[0];
  const vec3 n1 = glm::normalize(glm::normalize(eye - o1.Centre()) + vec3(0.0, 0.8, 0.0));
  // BRDF sampling alone finds the light through this wide lobe rarely: its noise would
  // need 16M rays for the power; it is tested at O3 and at the sharp highlight.
  ExpectPhongRadianceAgrees(
      scene,
      {"O1, exponent 5", o1.Centre() + o1.Radius() * n1, n1, &o1.GetMaterial(), 2000000, false},
      40);
  const Cube& o3 = scene.cubes[0];
  const vec3 top = o3.Centre() + vec3(0.1 * o3.Size(), 0.5 * o3.Size(), 0.3 * o3.Size());
  ExpectPhongRadianceAgrees(
      scene, {"O3's top, exponent 5", top, vec3(0, 1, 0), &o3.GetMaterial(), 8000000, true}, 50);
  const Scene sharp = CanonicalScene({"/objects/0/exponent=1000"});
  const Sphere& s1 = sharp.spheres[0];
  const vec3 h = HighlightNormal(sharp, s1);
  ExpectPhongRadianceAgrees(sharp,
                            {"O1's highlight, exponent 1000", s1.Centre() + s1.Radius() * h, h,
                             &s1.GetMaterial(), 2000000, true},
                            60);
}

// The radiance of a terminal wall point by Lambert's formula, asserting that the whole
// light is in its view (a 32 x 32 grid of the light's points tested, glass blocking).
double WallRadianceByLambert(const Scene& scene, vec3 w, vec3 n, double rho) {
  const Rectangle& light = scene.light->Shape();
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      const vec3 y = light.PointFromUV((i + 0.5) / 32.0, (j + 0.5) / 32.0);
      EXPECT_FALSE(scene.Occluded(OffsetRayOrigin(w, n, glm::normalize(y - w)), y))
          << "the wall point does not see the whole light";
    }
  }
  const std::vector<vec3> corners = {light.PointFromUV(0, 0), light.PointFromUV(1, 0),
                                     light.PointFromUV(1, 1), light.PointFromUV(0, 1)};
  return rho * kInvPi * scene.light->Radiance().x * PolygonCosineIntegral(w, n, corners);
}

// A mirror in the integrator: a camera ray that O3's top, made a mirror, reflects onto
// the back wall brings rho_mirror times the wall's radiance, Lambert's closed form.
TEST(MonteCarlo, AMirrorReflectsRhoTimesTheWallItShows) {
  const Scene scene = CanonicalScene({"/objects/2/material=mirror"});
  const MonteCarloIntegrator integrator(scene, {});
  const vec3 eye = scene.camera.eye;
  const vec3 p(0.56, 0.28, 0.2);  // on O3's top face
  const vec3 d = glm::normalize(p - eye);
  Hit first;
  ASSERT_TRUE(scene.Intersect(eye, d, first, true));
  ASSERT_LT(glm::length(first.point - p), 1e-9);
  ASSERT_EQ(first.material->type, MaterialType::Mirror);
  const vec3 r = Reflect(d, vec3(0, 1, 0));
  Hit wall;
  ASSERT_TRUE(scene.Intersect(OffsetRayOrigin(p, vec3(0, 1, 0), r), r, wall, true));
  ASSERT_EQ(wall.object, Wall::kBack) << "the reflection should land on the back wall";
  const double lw = WallRadianceByLambert(scene, wall.point, wall.normal, 0.75);
  const std::array<MeanAndError, 3> m = EstimateRadianceColour(integrator, eye, d, 200000, 61);
  for (int k = 0; k < 3; ++k) {
    const double exact = first.material->reflectance[k] * lw;
    const MeanAndError& e = m[static_cast<std::size_t>(k)];
    std::printf("mirror, channel %d: %.6f +- %.6f, rho Lambert %.6f\n", k, e.mean,
                e.StandardError(), exact);
    testing::ExpectNearWithPower(e.mean, e.StandardError(), exact, "channel " + std::to_string(k));
  }
}

// Glass in the integrator, both ways (split and choose): a camera ray through the glass
// sphere's centre crosses it at normal incidence, F = ((n - 1) / (n + 1))^2 at each face;
// what leaves toward the back wall is T^2 (1 + F^2 + F^4 + ...) = T^2 / (1 - F^2) of the
// wall's radiance (the reflections back toward the eye leave through the open front).
TEST(MonteCarlo, GlassAtNormalIncidenceTransmitsTSquaredOverOneMinusFSquared) {
  const Scene scene = CanonicalScene();
  const Sphere& o2 = scene.spheres[1];
  ASSERT_EQ(o2.GetMaterial().type, MaterialType::Glass);
  const vec3 eye = scene.camera.eye;
  const vec3 d = glm::normalize(o2.Centre() - eye);
  const double t = (0.0 - o2.Centre().z) / d.z;  // to the back wall, z = 0
  const vec3 w = o2.Centre() + t * d;
  ASSERT_GT(w.y, 0.0);
  const double lw = WallRadianceByLambert(scene, w, vec3(0, 0, 1), 0.75);
  const double ior = o2.GetMaterial().ior;
  const double f = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
  const double exact = (1.0 - f) * (1.0 - f) / (1.0 - f * f) * lw;
  for (const auto glass : {MonteCarloOptions::Glass::Split, MonteCarloOptions::Glass::Choose}) {
    MonteCarloOptions o;
    o.glass = glass;
    const MonteCarloIntegrator integrator(scene, o);
    const std::array<MeanAndError, 3> m = EstimateRadianceColour(integrator, eye, d, 200000, 62);
    const std::string name = glass == MonteCarloOptions::Glass::Split ? "split" : "choose";
    for (int k = 0; k < 3; ++k) {
      const MeanAndError& e = m[static_cast<std::size_t>(k)];
      std::printf("glass %s, channel %d: %.6f +- %.6f, T^2 / (1 - F^2) Lambert %.6f\n",
                  name.c_str(), k, e.mean, e.StandardError(), exact);
      testing::ExpectNearWithPower(e.mean, e.StandardError(), exact,
                                   name + ", channel " + std::to_string(k));
    }
  }
}

// Russian roulette adds no bias: with diffuse walls (where it ends most paths) the image
// agrees with one whose roulette threshold is so small that it ends almost none.
TEST(MonteCarlo, RussianRouletteAddsNoBias) {
  const Scene scene = CanonicalScene();
  MonteCarloOptions o;
  o.walls = MonteCarloOptions::Walls::Diffuse;
  o.maxDepth = scene.mc.maxDepth;  // as glint render: both sides end there
  ASSERT_EQ(o.rouletteThreshold, MonteCarloIntegrator::kRouletteThreshold);
  const MonteCarloIntegrator pilotIntegrator(scene, o);
  const Image pilot =
      testing::RenderWithSampler(scene, pilotIntegrator, SamplerKind::Random, kSize, 16, 99);
  const BlockEstimates roulette = RenderBlocks(scene, o, kSize, kBlock, 64, kRuns, 700, pilot);
  o.rouletteThreshold = 1e-6;
  const BlockEstimates none = RenderBlocks(scene, o, kSize, kBlock, 64, kRuns, 800, pilot);
  ExpectBlocksAgreeWithPower("roulette against almost none", roulette, none);
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
        Camera camera(scene.wall, scene.camera, 24, 24);
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
