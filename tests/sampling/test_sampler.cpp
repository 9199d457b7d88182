// The samplers (random, stratified, sobol): the Sobol sequence and its scrambles, the
// uniformity of every sampler's first dimensions (chi-square), their discrepancy, their
// convergence on a smooth integrand, their unbiasedness against Lambert's closed form,
// images that agree, and pixels whose noise is not correlated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/image/BiasTest.hpp"
#include "glint/sampling/LowDiscrepancy.hpp"
#include "glint/sampling/Sampler.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Power.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::CanonicalScene;
using testing::ChiSquare;
using testing::ExpectAgreementWithPower;
using testing::MeanAndError;
using testing::PolygonCosineIntegral;
using testing::RenderWithSampler;
using testing::SidakAlpha;

constexpr SamplerKind kKinds[] = {SamplerKind::Random, SamplerKind::Stratified, SamplerKind::Sobol};

// The first eight dimensions of `samples` samples of one pixel, sample-major.
std::vector<double> FirstDimensions(SamplerKind kind, std::uint64_t seed, std::uint64_t pixel,
                                    int samples) {
  Sampler sampler(kind, seed, pixel, 0, 0, samples);
  std::vector<double> out;
  for (int i = 0; i < samples; ++i) {
    sampler.StartSample(i);
    for (std::uint32_t d = 0; d < 6; d += 2) {
      const Sample2 p = sampler.Get2D(d);
      out.push_back(p.u);
      out.push_back(p.v);
    }
    out.push_back(sampler.Get1D(6));
    out.push_back(sampler.Get1D(7));
  }
  return out;
}

TEST(Sampler, SobolPointsAreTheSequencesAndTheTablesAgreeWithTheLoop) {
  // van der Corput and the second dimension (x + 1), by the index's bits (not Gray code).
  const double second[] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  const double first[] = {0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  for (std::uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(Sobol4::Sample(i, 0) * 0x1.0p-32, first[i]) << i;
    EXPECT_EQ(Sobol4::Sample(i, 1) * 0x1.0p-32, second[i]) << i;
  }
  Pcg32 rng(3, 3);
  for (int n = 0; n < 20000; ++n) {
    const std::uint32_t i = rng.NextU32();
    for (int d = 0; d < Sobol4::kDimensions; ++d) {
      ASSERT_EQ(Sobol4::SampleReversed(ReverseBits32(i), d), ReverseBits32(Sobol4::Sample(i, d)));
    }
  }
  // Each dimension's first 2^m points fill the 2^m intervals of width 2^-m once (a
  // (0, 1)-sequence), and dimensions 0 and 1 together are a (0, 2)-sequence: the first
  // 2^m points put one point in each elementary interval of area 2^-m.
  for (int m = 1; m <= 12; ++m) {
    const std::uint32_t points = 1U << static_cast<unsigned>(m);
    for (int d = 0; d < 4; ++d) {
      std::vector<int> count(points, 0);
      for (std::uint32_t i = 0; i < points; ++i) ++count[Sobol4::Sample(i, d) >> (32U - m)];
      ASSERT_EQ(*std::min_element(count.begin(), count.end()), 1) << "dimension " << d;
    }
    for (int k = 0; k <= m; ++k) {  // intervals 2^-k wide, 2^-(m-k) high
      const auto h = static_cast<unsigned>(m - k);
      std::vector<int> count(points, 0);
      for (std::uint32_t i = 0; i < points; ++i) {
        const std::uint32_t cx = k == 0 ? 0 : Sobol4::Sample(i, 0) >> (32U - k);
        const std::uint32_t cy = h == 0 ? 0 : Sobol4::Sample(i, 1) >> (32U - h);
        ++count[(cx << h) | cy];
      }
      ASSERT_EQ(*std::min_element(count.begin(), count.end()), 1) << "m " << m << ", k " << k;
    }
  }
}

TEST(Sampler, OwenScrambleKeepsTheNestedStrata) {
  // A nested uniform scramble maps values that share their first k bits to values that
  // share their first k bits, and is a bijection.
  Pcg32 rng(9, 1);
  for (int s = 0; s < 50; ++s) {
    const std::uint32_t seed = rng.NextU32();
    std::set<std::uint32_t> images;
    for (std::uint32_t top = 0; top < 4096; ++top)
      images.insert(OwenScramble(top << 20U, seed) >> 20U);
    ASSERT_EQ(images.size(), 4096U);
    for (int n = 0; n < 2000; ++n) {
      const std::uint32_t x = rng.NextU32();
      const int k = static_cast<int>(rng.NextU32() % 32U);
      const std::uint32_t mask = k == 0 ? 0U : ~0U << static_cast<unsigned>(32 - k);
      const std::uint32_t y = (x & mask) | (rng.NextU32() & ~mask);
      ASSERT_EQ(OwenScramble(x, seed) & mask, OwenScramble(y, seed) & mask);
    }
  }
}

TEST(Sampler, PermutationElementIsAPermutation) {
  for (const std::uint32_t n : {1U, 2U, 3U, 7U, 64U, 100U, 1000U}) {
    for (std::uint32_t seed = 1; seed < 20; ++seed) {
      std::set<std::uint32_t> seen;
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t p = PermutationElement(i, n, seed * 0x9e3779b9U);
        ASSERT_LT(p, n);
        seen.insert(p);
      }
      ASSERT_EQ(seen.size(), n);
    }
  }
}

// Chi-square of 1D projections (64 bins) of the first eight dimensions and of 2D
// projections (16 x 16 cells) of pairs: those the integrators use together, pairs across
// the stratified pairs, and pairs across Sobol's groups of four (0, 4), (2, 6), whose
// shuffled indices must not leave them dependent.
TEST(Sampler, EverySamplersFirstDimensionsAreUniform) {
  constexpr int kPixels = 1024;
  constexpr int kSamples = 64;
  const int pairs[][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {1, 2}, {3, 4}, {0, 4}, {2, 6}, {0, 2}};
  const int tests = 3 * (8 + static_cast<int>(std::size(pairs)));
  const double alpha = SidakAlpha(1e-3, tests);
  for (const SamplerKind kind : kKinds) {
    std::vector<std::vector<double>> oneD(8, std::vector<double>(64, 0.0));
    std::vector<std::vector<double>> twoD(std::size(pairs), std::vector<double>(256, 0.0));
    for (int p = 0; p < kPixels; ++p) {
      const std::vector<double> x =
          FirstDimensions(kind, 7, static_cast<std::uint64_t>(p), kSamples);
      for (int i = 0; i < kSamples; ++i) {
        const double* s = &x[static_cast<std::size_t>(i) * 8];
        for (int d = 0; d < 8; ++d) {
          ASSERT_GE(s[d], 0.0);
          ASSERT_LT(s[d], 1.0);
          oneD[static_cast<std::size_t>(d)][static_cast<std::size_t>(s[d] * 64.0)] += 1.0;
        }
        for (std::size_t q = 0; q < std::size(pairs); ++q) {
          const auto cx = static_cast<std::size_t>(s[pairs[q][0]] * 16.0);
          const auto cy = static_cast<std::size_t>(s[pairs[q][1]] * 16.0);
          twoD[q][cy * 16 + cx] += 1.0;
        }
      }
    }
    const double n = kPixels * kSamples;
    for (int d = 0; d < 8; ++d) {
      const auto r = ChiSquare(oneD[static_cast<std::size_t>(d)], std::vector<double>(64, n / 64));
      EXPECT_GT(r.pValue, alpha) << SamplerName(kind) << " dimension " << d << ": chi2 "
                                 << r.statistic << " on " << r.dof << " dof";
    }
    for (std::size_t q = 0; q < std::size(pairs); ++q) {
      const auto r = ChiSquare(twoD[q], std::vector<double>(256, n / 256));
      EXPECT_GT(r.pValue, alpha) << SamplerName(kind) << " dimensions " << pairs[q][0] << ", "
                                 << pairs[q][1] << ": chi2 " << r.statistic << " on " << r.dof
                                 << " dof";
    }
  }
}

// The star discrepancy of 2D points: the largest |fraction of points in [0, x) x [0, y) -
// xy| over the boxes whose corner lies on the grid of the points' coordinates (closed
// and open boxes both), which is where the supremum is reached.
double StarDiscrepancy(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> xs = x;
  std::vector<double> ys = y;
  xs.push_back(1.0);
  ys.push_back(1.0);
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (const double bx : xs) {
    for (const double by : ys) {
      int open = 0;
      int closed = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        open += x[i] < bx && y[i] < by ? 1 : 0;
        closed += x[i] <= bx && y[i] <= by ? 1 : 0;
      }
      d = std::max({d, bx * by - open / n, closed / n - bx * by});
    }
  }
  return d;
}

TEST(Sampler, StratifiedAndSobolHaveLowerStarDiscrepancyThanRandom) {
  constexpr int kSamples = 128;
  constexpr int kPixels = 12;
  for (const std::uint32_t pair : {0U, 2U, 4U}) {
    double mean[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      for (int p = 0; p < kPixels; ++p) {
        const std::vector<double> s =
            FirstDimensions(kKinds[k], 3, static_cast<std::uint64_t>(p), kSamples);
        std::vector<double> x;
        std::vector<double> y;
        for (int i = 0; i < kSamples; ++i) {
          x.push_back(s[static_cast<std::size_t>(i) * 8 + pair]);
          y.push_back(s[static_cast<std::size_t>(i) * 8 + pair + 1]);
        }
        mean[k] += StarDiscrepancy(x, y) / kPixels;
      }
    }
    std::printf(
        "dimensions %u, %u, %d points: star discrepancy random %.4f, stratified %.4f, "
        "sobol %.4f\n",
        pair, pair + 1, kSamples, mean[0], mean[1], mean[2]);
    EXPECT_LT(mean[1], 0.6 * mean[0]) << "stratified, dimensions " << pair;
    EXPECT_LT(mean[2], 0.5 * mean[0]) << "sobol, dimensions " << pair;
  }
}

// A wall point that sees all of the light: its radiance, by Lambert, and the estimate of
// `samples` samples of one pixel's sampler (the light point is node 0's first two
// dimensions).
struct SmoothIntegrand {
  Scene scene = CanonicalScene({"/objects=[]"});
  MonteCarloIntegrator integrator{scene, {}};
  vec3 from{0.7, 0.3, 0.5};
  vec3 point{0.7, 0.3, 0.0};  // the back wall
  double exact = 0.0;

  SmoothIntegrand() {
    const Rectangle& light = scene.light->Shape();
    const std::vector<vec3> corners = {light.PointFromUV(0, 0), light.PointFromUV(1, 0),
                                       light.PointFromUV(1, 1), light.PointFromUV(0, 1)};
    exact = 0.75 * kInvPi * 50.0 * PolygonCosineIntegral(point, vec3(0, 0, 1), corners);
  }
  double Estimate(SamplerKind kind, std::uint64_t seed, int samples) const {
    Sampler sampler(kind, seed, 0, 0, 0, samples);
    RayTree tree;
    RenderStats stats;
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
      sampler.StartSample(i);
      tree.Clear();
      Ray ray;
      ray.start = from;
      ray.direction = glm::normalize(point - from);
      sum += integrator.Trace(tree, tree.Add(ray), PixelShaft{}, sampler, stats).y;
    }
    return sum / samples;
  }
};

TEST(Sampler, ErrorOnASmoothIntegrandFallsFasterThanOneOverRootNForStratifiedAndSobol) {
  const SmoothIntegrand f;
  constexpr int kScrambles = 32;
  const int counts[] = {16, 64, 256, 1024, 4096};
  for (const SamplerKind kind : kKinds) {
    std::vector<double> logN;
    std::vector<double> logError;
    for (const int n : counts) {
      double squared = 0.0;
      for (int s = 0; s < kScrambles; ++s) {
        const double e = f.Estimate(kind, 1000 + static_cast<std::uint64_t>(s), n) - f.exact;
        squared += e * e;
      }
      logN.push_back(std::log(n));
      logError.push_back(0.5 * std::log(squared / kScrambles));
    }
    // Least-squares slope of log RMSE against log N.
    double mx = 0.0;
    double my = 0.0;
    for (std::size_t i = 0; i < logN.size(); ++i) {
      mx += logN[i] / static_cast<double>(logN.size());
      my += logError[i] / static_cast<double>(logN.size());
    }
    double sxy = 0.0;
    double sxx = 0.0;
    for (std::size_t i = 0; i < logN.size(); ++i) {
      sxy += (logN[i] - mx) * (logError[i] - my);
      sxx += (logN[i] - mx) * (logN[i] - mx);
    }
    const double slope = sxy / sxx;
    std::printf("%s: RMSE ~ N^%.3f over N = 16..4096 (%d scrambles; N = 4096: %.3g of %.4f)\n",
                SamplerName(kind), slope, kScrambles, std::exp(logError.back()), f.exact);
    if (kind == SamplerKind::Random) {
      EXPECT_NEAR(slope, -0.5, 0.12);
    } else {
      EXPECT_LT(slope, -0.8) << SamplerName(kind);  // jittered: -1; Owen-scrambled: -1.5
    }
  }
}

TEST(Sampler, EverySamplerIsUnbiasedForLambertsFormula) {
  const SmoothIntegrand f;
  for (const SamplerKind kind : kKinds) {
    MeanAndError m;
    for (std::uint64_t seed = 1; seed <= 4000; ++seed) m.Add(f.Estimate(kind, seed, 16));
    // The test can see a 0.1% bias: four standard errors are well below it.
    ASSERT_LT(4.0 * m.StandardError(), 1e-3 * f.exact) << SamplerName(kind);
    EXPECT_NEAR(m.mean, f.exact, 4.0 * m.StandardError()) << SamplerName(kind);
    std::printf("%s: %.7f +- %.7f, Lambert %.7f (%+.2f standard errors)\n", SamplerName(kind),
                m.mean, m.StandardError(), f.exact, (m.mean - f.exact) / m.StandardError());
  }
}

// Stratified and sobol images agree with random ones, block by block and in each
// channel's whole-image mean, in both wall modes and in Whitted mode, through the shafts
// of `glint render`; each comparison shows it would see a 1% bias (support/Power.hpp).
TEST(Sampler, ImagesOfTheThreeSamplersAgreeBlockByBlock) {
  const Scene scene = CanonicalScene();
  MonteCarloOptions diffuse;
  diffuse.walls = MonteCarloOptions::Walls::Diffuse;
  const MonteCarloIntegrator terminal(scene, {});
  const MonteCarloIntegrator global(scene, diffuse);
  const WhittedIntegrator whitted(scene, 10);
  const Integrator* integrators[] = {&terminal, &global, &whitted};
  const char* names[] = {"mc terminal", "mc diffuse", "whitted"};
  // Rays per pixel for a relative standard error of the weighted mean near 0.15%.
  const int spp[] = {64, 512, 32};
  for (int k = 0; k < 3; ++k) {
    const Integrator& integrator = *integrators[k];
    const Image pilot = RenderWithSampler(scene, integrator, SamplerKind::Random, 64, 8, 99);
    const Image r1 = RenderWithSampler(scene, integrator, SamplerKind::Random, 64, spp[k], 11);
    const Image r2 = RenderWithSampler(scene, integrator, SamplerKind::Random, 64, spp[k], 12);
    for (const SamplerKind kind : {SamplerKind::Stratified, SamplerKind::Sobol}) {
      const Image a = RenderWithSampler(scene, integrator, kind, 64, spp[k], 21);
      const Image b = RenderWithSampler(scene, integrator, kind, 64, spp[k], 22);
      ExpectAgreementWithPower(std::string(names[k]) + ", " + SamplerName(kind) + " against random",
                               a, b, r1, &r2, pilot);
    }
  }
}

// The noise of one pixel says nothing of its neighbour's: on the back wall of an empty
// room (flat, evenly lit) the difference of two renders (pure noise, no image) has no
// autocorrelation at small lags beyond what chance gives. The standard error of the
// coefficient sum pq / sqrt(sum p^2 sum q^2) is sqrt(sum p^2 q^2 / (sum p^2 sum q^2)),
// which allows for a variance that changes across the wall.
TEST(Sampler, NeighbouringPixelsNoiseIsUncorrelated) {
  const Scene scene = CanonicalScene({"/objects=[]"});
  const MonteCarloIntegrator integrator(scene, {});
  constexpr int kSize = 128;
  constexpr int kLo = 40;  // the back wall: pixels [40, 88) in x and y
  constexpr int kHi = 88;
  const int lags[][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}, {2, 0}, {0, 2}, {3, 0}};
  for (const SamplerKind kind : kKinds) {
    const Image a = RenderWithSampler(scene, integrator, kind, kSize, 4, 5);
    const Image b = RenderWithSampler(scene, integrator, kind, kSize, 4, 6);
    std::vector<double> d(static_cast<std::size_t>(kSize * kSize), 0.0);
    for (int y = kLo; y < kHi; ++y) {
      for (int x = kLo; x < kHi; ++x) {
        const Colour c = a.At(x, y) - b.At(x, y);
        d[static_cast<std::size_t>(y * kSize + x)] = c.x + c.y + c.z;
      }
    }
    double worst = 0.0;
    for (const auto& lag : lags) {
      double sxy = 0.0;
      double sxx = 0.0;
      double syy = 0.0;
      double sxxyy = 0.0;
      for (int y = kLo; y < kHi; ++y) {
        for (int x = kLo; x < kHi; ++x) {
          const int x2 = x + lag[0];
          const int y2 = y + lag[1];
          if (x2 < kLo || x2 >= kHi || y2 >= kHi) continue;
          const double p = d[static_cast<std::size_t>(y * kSize + x)];
          const double q = d[static_cast<std::size_t>(y2 * kSize + x2)];
          sxy += p * q;
          sxx += p * p;
          syy += q * q;
          sxxyy += p * p * q * q;
        }
      }
      const double rho = sxy / std::sqrt(sxx * syy);
      const double se = std::sqrt(sxxyy / (sxx * syy));
      worst = std::max(worst, std::abs(rho) / se);
      EXPECT_LT(std::abs(rho), 4.5 * se)
          << SamplerName(kind) << ", lag (" << lag[0] << ", " << lag[1] << "): " << rho;
    }
    std::printf("%s: largest |autocorrelation| on the back wall %.2f standard errors\n",
                SamplerName(kind), worst);
  }
}

TEST(Sampler, SobolPassesContinueOneSequenceAndImagesDoNotDependOnThreads) {
  const Scene scene = CanonicalScene();
  const MonteCarloIntegrator integrator(scene, {});
  const auto twoPasses = [&](SamplerKind kind) {
    Camera camera(scene.wall, scene.camera, 16, 16);
    RenderOptions options;
    options.sampler = kind;
    options.raysPerPixel = 8;
    camera.Render(integrator, options);
    options.pass = 1;
    options.firstSample = 8;
    camera.Render(integrator, options);
    return camera.ToImage();
  };
  const Image one = RenderWithSampler(scene, integrator, SamplerKind::Sobol, 16, 16, 1);
  const Image two = twoPasses(SamplerKind::Sobol);
  double largest = 0.0;
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      largest = std::max(largest, MaxComponent(glm::abs(one.At(x, y) - two.At(x, y))));
    }
  }
  EXPECT_LT(largest, 1e-12);  // the same 16 samples, summed in two parts
  for (const SamplerKind kind : kKinds) {
    const Image t1 = RenderWithSampler(scene, integrator, kind, 32, 8, 3, 1);
    const Image t2 = RenderWithSampler(scene, integrator, kind, 32, 8, 3, 2);
    EXPECT_EQ(t1.Pixels(), t2.Pixels()) << SamplerName(kind);
  }
}

}  // namespace
}  // namespace glint
