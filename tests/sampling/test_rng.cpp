// The per-pixel random generator: uniforms in [0, 1) on the 2^-32 grid, evenly spread,
// pairs (u, v) evenly spread over the square, and distinct streams for neighbouring
// pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glint/sampling/Rng.hpp"
#include "support/Statistics.hpp"

namespace glint {
namespace {

using testing::ChiSquare;
using testing::SidakAlpha;

constexpr double kFamilyAlpha = 0.01;
constexpr int kTests = 3;  // chi-square tests in this file, for Sidak's correction

TEST(Pcg32, UniformLiesOnTheGridInTheUnitInterval) {
  Pcg32 rng(1, 2);
  double lowest = 1.0;
  double highest = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    const double u = rng.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const double scaled = u * 0x1.0p32;
    ASSERT_EQ(scaled, std::floor(scaled)) << u << " is not a multiple of 2^-32";
    lowest = std::min(lowest, u);
    highest = std::max(highest, u);
  }
  EXPECT_LT(lowest, 1e-5);  // expected 1e-6
  EXPECT_GT(highest, 1.0 - 1e-5);
}

TEST(Pcg32, UniformFitsTheUniformDensity) {
  constexpr int kBins = 1000;
  constexpr int kSamples = 1000000;
  std::vector<double> observed(kBins, 0.0);
  Pcg32 rng(3, 4);
  for (int i = 0; i < kSamples; ++i) {
    observed[static_cast<std::size_t>(rng.Uniform() * kBins)] += 1.0;
  }
  const std::vector<double> expected(kBins, static_cast<double>(kSamples) / kBins);
  const auto r = ChiSquare(observed, expected);
  EXPECT_GT(r.pValue, SidakAlpha(kFamilyAlpha, kTests))
      << "chi^2 = " << r.statistic << " with " << r.dof << " dof";
}

// Next-event estimation and the pixel jitter draw their u and v one after the other:
// consecutive pairs must cover the square evenly.
TEST(Pcg32, ConsecutivePairsFitTheUnitSquare) {
  constexpr int kSide = 32;
  constexpr int kSamples = 1000000;
  std::vector<double> observed(kSide * kSide, 0.0);
  Pcg32 rng(5, 6);
  for (int i = 0; i < kSamples; ++i) {
    const auto a = static_cast<int>(rng.Uniform() * kSide);
    const auto b = static_cast<int>(rng.Uniform() * kSide);
    observed[static_cast<std::size_t>(a * kSide + b)] += 1.0;
  }
  const std::vector<double> expected(kSide * kSide,
                                     static_cast<double>(kSamples) / (kSide * kSide));
  const auto r = ChiSquare(observed, expected);
  EXPECT_GT(r.pValue, SidakAlpha(kFamilyAlpha, kTests))
      << "chi^2 = " << r.statistic << " with " << r.dof << " dof";
}

// Neighbouring pixels and passes get unrelated streams: the first draws of pixel i and
// pixel i + 1 are correlated no more than chance allows.
TEST(Pcg32, NeighbouringPixelsGetUnrelatedStreams) {
  constexpr int kPixels = 100000;
  double sumXY = 0.0;
  double sumXYPass = 0.0;
  for (int i = 0; i < kPixels; ++i) {
    const auto index = static_cast<std::uint64_t>(i);
    Pcg32 a = Pcg32::ForPixel(1, index);
    Pcg32 b = Pcg32::ForPixel(1, index + 1);
    Pcg32 c = Pcg32::ForPixel(1, index, 1);
    const double x = a.Uniform() - 0.5;
    sumXY += x * (b.Uniform() - 0.5);
    sumXYPass += x * (c.Uniform() - 0.5);
  }
  // Each product has mean 0 and standard deviation 1/12 for independent draws:
  // 5 standard errors are 5 / (12 sqrt(N)) = 1.3e-3.
  const double limit = 5.0 / (12.0 * std::sqrt(static_cast<double>(kPixels)));
  EXPECT_LT(std::abs(sumXY / kPixels), limit);
  EXPECT_LT(std::abs(sumXYPass / kPixels), limit);
}

}  // namespace
}  // namespace glint
