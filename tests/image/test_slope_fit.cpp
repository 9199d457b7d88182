// The slope of a convergence study and its error bar, on studies whose truth is known:
// a power law y = x^-1 with noisy errors and noisy times, as glint converge measures them.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/core/Math.hpp"
#include "glint/image/SlopeFit.hpp"

namespace glint {
namespace {

double Gaussian(Pcg32& rng) {
  return std::sqrt(-2.0 * std::log(1.0 - rng.Uniform())) * std::cos(2.0 * kPi * rng.Uniform());
}

// Eight rungs, x = 2^k, `repeats` each: times off by 10% (lognormal) and, one run in
// ten, preempted (three times as long); errors off by 30%.
std::vector<Rung> Study(Pcg32& rng, int repeats) {
  std::vector<Rung> rungs(8);
  for (int k = 0; k < 8; ++k) {
    const double x = std::ldexp(1.0, k);
    for (int j = 0; j < repeats; ++j) {
      const double preempted = rng.Uniform() < 0.1 ? 3.0 : 1.0;
      rungs[k].x.push_back(x * std::exp(0.1 * Gaussian(rng)) * preempted);
      rungs[k].y.push_back(std::exp(0.3 * Gaussian(rng)) / x);
    }
  }
  return rungs;
}

TEST(SlopeFit, MedianAndMean) {
  EXPECT_EQ(MedianOf({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(MedianOf({4.0, 1.0, 2.0, 3.0}), 2.5);
  EXPECT_EQ(MeanOf({1.0, 2.0, 6.0}), 3.0);
  EXPECT_TRUE(std::isnan(MedianOf({})));
}

TEST(SlopeFit, ExactPowerLaw) {
  std::vector<Rung> rungs;
  for (int k = 0; k < 5; ++k) {
    const double x = std::ldexp(1.0, k);
    const double y = 2.0 * std::pow(x, -0.5);
    rungs.push_back({{x, x, x}, {y, y, y}, {}});
  }
  Pcg32 rng(1, 1);
  const Slope s = FitSlope(rungs, rng);
  EXPECT_NEAR(s.value, -0.5, 1e-12);
  EXPECT_NEAR(s.standardError, 0.0, 1e-12);
  EXPECT_EQ(s.points, 5);
  EXPECT_NEAR(s.logY - (std::log(2.0) - 0.5 * s.logX), 0.0, 1e-12);  // through the centroid
}

TEST(SlopeFit, OneRungHasNoSlope) {
  Pcg32 rng(1, 1);
  EXPECT_TRUE(std::isnan(FitSlope({{{1.0, 1.1}, {0.5, 0.6}, {}}}, rng).value));
}

// The error bar is what it claims: over 300 studies, the slopes spread as their standard
// errors say, or a little less (the bootstrap of a median with outliers is cautious: 1.2x
// to 1.35x here; ratio within [0.75, 1.6]), and lie within two standard errors of the
// truth at least 88% of the time. Dropping the bootstrap (an error bar of 0) or
// resampling one repeat for all (too small) fails both.
TEST(SlopeFit, StandardErrorMatchesTheSpreadOfSlopes) {
  Pcg32 data(7, 1);
  Pcg32 boot(8, 2);
  for (const int repeats : {3, 9}) {
    const int studies = 300;
    double sum = 0.0;
    double sum2 = 0.0;
    double se2 = 0.0;
    int covered = 0;
    for (int i = 0; i < studies; ++i) {
      const Slope s = FitSlope(Study(data, repeats), boot, 400);
      sum += s.value;
      sum2 += s.value * s.value;
      se2 += s.standardError * s.standardError;
      covered += std::abs(s.value + 1.0) < 2.0 * s.standardError ? 1 : 0;
    }
    const double mean = sum / studies;
    const double spread = std::sqrt((sum2 - studies * mean * mean) / (studies - 1));
    const double claimed = std::sqrt(se2 / studies);
    SCOPED_TRACE("repeats " + std::to_string(repeats));
    EXPECT_NEAR(mean, -1.0, 4.0 * spread / std::sqrt(studies));
    EXPECT_GT(claimed / spread, 0.75);
    EXPECT_LT(claimed / spread, 1.6);
    EXPECT_GE(covered, 0.88 * studies);
  }
}

// Rounds that share their load: each rung's repeats come in six rounds, and a round's
// times are all off by one factor (a busy spell, 20%). Resampled round by round, the error
// bar covers it (1.06 of the spread measured); resampled repeat by repeat, it is too
// small (0.75).
TEST(SlopeFit, RoundsShareTheirLoad) {
  Pcg32 data(9, 1);
  Pcg32 boot(10, 2);
  const auto study = [&](bool blocks) {
    std::vector<Rung> rungs(8);
    for (int k = 0; k < 8; ++k) {
      const double x = std::ldexp(1.0, k);
      for (int round = 0; round < 6; ++round) {
        const double spell = std::exp(0.2 * Gaussian(data));
        for (int j = 0; j < 3; ++j) {
          rungs[k].x.push_back(x * spell * std::exp(0.02 * Gaussian(data)));
          rungs[k].y.push_back(std::exp(0.05 * Gaussian(data)) / x);
          if (blocks) rungs[k].block.push_back(round);
        }
      }
    }
    return rungs;
  };
  for (const bool blocks : {true, false}) {
    const int studies = 300;
    double sum = 0.0;
    double sum2 = 0.0;
    double se2 = 0.0;
    for (int i = 0; i < studies; ++i) {
      const Slope s = FitSlope(study(blocks), boot, 300);
      sum += s.value;
      sum2 += s.value * s.value;
      se2 += s.standardError * s.standardError;
    }
    const double mean = sum / studies;
    const double ratio =
        std::sqrt(se2 / studies) / std::sqrt((sum2 - studies * mean * mean) / (studies - 1));
    SCOPED_TRACE(blocks ? "by rounds" : "by repeats");
    if (blocks) {
      EXPECT_GT(ratio, 0.9);
      EXPECT_LT(ratio, 1.6);
    } else {
      EXPECT_LT(ratio, 0.85);
    }
  }
}

}  // namespace
}  // namespace glint
