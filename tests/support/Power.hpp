// Agreement tests that prove their power when they run (issue #29). A test of "these two
// estimators give the same image" passes trivially if it is too small to see a bias, so
// each one here also shows, on its own data, that a 1% bias would fail it:
//  - it computes the standard error of what it compares and asserts that 1% of the mean
//    is at least kPowerSigmas of them, in every channel;
//  - it feeds its own decision the same data with one side's channel scaled by 1.01 (and
//    by 0.99), each channel in turn, and asserts that the decision refuses it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "glint/image/BiasTest.hpp"
#include "glint/image/Image.hpp"

namespace glint::testing {

// A 1% bias must be at least this many standard errors of the comparison.
inline constexpr double kPowerSigmas = 4.0;
// The whole-image means may differ by this many standard errors, in each channel.
inline constexpr double kMeanSigmas = 4.0;

// The whole image's mean, channel by channel, each pixel weighted by 1 / (p + 0.05), p the
// largest value of a pilot render in the pixel's 3 x 3 neighbourhood: a mean of relative
// values, which the few pixels on the light's edge (radiance 50 next to 0) do not swamp
// as they swamp a plain mean. The neighbourhood's maximum keeps a pixel next to a bright
// feature the pilot happened to miss (the light seen through the glass) from a weight of
// 20: measured on 32 x 32 pixels of the Phong test scene, it takes the relative standard
// error from 0.22% to 0.035%, against 0.36% unweighted. The pilot is a render independent
// of A, B, R1 and R2, so the weights are fixed and the statistic
//   D = sum_i w_i (E_i - R_i),  E = (A + B) / 2,  R = (R1 + R2) / 2,
// is linear in the renders: Var D = sum_i w_i^2 ((A_i - B_i)^2 + (R1_i - R2_i)^2) / 4,
// unbiased for independent pairs, as in TestBias. With R2 null, R1 is taken as exact.
inline Image PilotWeights(const Image& pilot) {
  Image w(pilot.Width(), pilot.Height());
  for (int y = 0; y < pilot.Height(); ++y) {
    for (int x = 0; x < pilot.Width(); ++x) {
      Colour m(0.0);
      for (int v = std::max(0, y - 1); v <= std::min(pilot.Height() - 1, y + 1); ++v) {
        for (int u = std::max(0, x - 1); u <= std::min(pilot.Width() - 1, x + 1); ++u)
          m = glm::max(m, pilot.At(u, v));
      }
      w.At(x, y) = 1.0 / (m + 0.05);
    }
  }
  return w;
}

struct ChannelMeans {
  double ratio[3] = {1.0, 1.0, 1.0};       // sum w E / sum w R
  double relativeSe[3] = {0.0, 0.0, 0.0};  // of that ratio
  double z[3] = {0.0, 0.0, 0.0};
};

inline ChannelMeans WeightedChannelMeans(const Image& a, const Image& b, const Image& r1,
                                         const Image* r2, const Image& pilot,
                                         Colour scale = Colour(1.0)) {
  ChannelMeans m;
  const Image weights = PilotWeights(pilot);
  for (int k = 0; k < 3; ++k) {
    double e = 0.0;
    double r = 0.0;
    double var = 0.0;
    for (int y = 0; y < r1.Height(); ++y) {
      for (int x = 0; x < r1.Width(); ++x) {
        const double w = weights.At(x, y)[k];
        const double va = scale[k] * a.At(x, y)[k];
        const double vb = scale[k] * b.At(x, y)[k];
        const double v1 = r1.At(x, y)[k];
        const double v2 = r2 ? r2->At(x, y)[k] : v1;
        e += w * 0.5 * (va + vb);
        r += w * 0.5 * (v1 + v2);
        var += w * w * 0.25 * ((va - vb) * (va - vb) + (v1 - v2) * (v1 - v2));
      }
    }
    const double se = std::sqrt(var);
    m.ratio[k] = e / r;
    m.relativeSe[k] = se / r;
    m.z[k] = se > 0.0 ? (e - r) / se : (e == r ? 0.0 : INFINITY);
  }
  return m;
}

// The decision: every block and channel agrees (TestBias: Sidak-corrected family level
// 1e-3 over its block tests) and each channel's weighted whole-image mean lies within
// kMeanSigmas standard errors (three normal tests at 6.3e-5 each). Family false-alarm
// rate of one call: about 1.2e-3.
struct Agreement {
  BiasVerdict blocks;
  ChannelMeans means;
  bool agree = true;
};

inline Agreement Agree(const Image& a, const Image& b, const Image& r1, const Image* r2,
                       const Image& pilot, Colour scale = Colour(1.0)) {
  Agreement g;
  g.blocks = scale == Colour(1.0) ? TestBias(a, b, r1, r2)
                                  : TestBias(a.Scaled(scale), b.Scaled(scale), r1, r2);
  g.means = WeightedChannelMeans(a, b, r1, r2, pilot, scale);
  g.agree = g.blocks.agree;
  for (int k = 0; k < 3; ++k) g.agree = g.agree && std::abs(g.means.z[k]) <= kMeanSigmas;
  return g;
}

// A and B (one estimator, two seeds) agree with R1 and R2 (another, or the same with
// other settings), and the test has the power to see a 1% bias in any channel.
inline void ExpectAgreementWithPower(const std::string& label, const Image& a, const Image& b,
                                     const Image& r1, const Image* r2, const Image& pilot) {
  const Agreement g = Agree(a, b, r1, r2, pilot);
  std::printf("%s: block max z %.2f (limit %.2f); weighted means", label.c_str(),
              g.blocks.maxBlockZ, g.blocks.blockLimit);
  for (int k = 0; k < 3; ++k) {
    std::printf(" %.5f +- %.5f (z %+.2f)", g.means.ratio[k], g.means.relativeSe[k], g.means.z[k]);
  }
  std::printf("\n");
  EXPECT_TRUE(g.agree) << label << ": " << g.blocks.failedBlocks << " blocks beyond "
                       << g.blocks.blockLimit << ", channel z " << g.means.z[0] << ", "
                       << g.means.z[1] << ", " << g.means.z[2];
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(kPowerSigmas * g.means.relativeSe[k], 0.01)
        << label << ", channel " << k << ": a 1% bias would be only "
        << 0.01 / g.means.relativeSe[k] << " standard errors";
  }
  // One channel at a time, up and down: each must be refused.
  for (int k = 0; k < 3; ++k) {
    for (const double s : {1.01, 0.99}) {
      Colour scale(1.0);
      scale[k] = s;
      EXPECT_FALSE(Agree(a, b, r1, r2, pilot, scale).agree)
          << label << ": channel " << k << " of A and B scaled by " << s
          << " passes: the test cannot see a 1% bias";
    }
  }
}

// A mean and its standard error against an exact value: within `sigmas` of it, and with
// the power to see a 1% bias: 1% of the value is at least kPowerSigmas standard errors,
// and the mean scaled by 1.01 or 0.99 falls outside `sigmas` of it.
inline void ExpectNearWithPower(double mean, double se, double exact, const std::string& label,
                                double sigmas = 3.0) {
  EXPECT_LE(kPowerSigmas * se, 0.01 * std::abs(exact))
      << label << ": a 1% bias would be only " << 0.01 * std::abs(exact) / se << " standard errors";
  EXPECT_LE(std::abs(mean - exact), sigmas * se) << label << ": " << mean << " against " << exact;
  for (const double s : {1.01, 0.99}) {
    EXPECT_GT(std::abs(s * mean - exact), sigmas * se)
        << label << ": the mean scaled by " << s << " passes: the test cannot see a 1% bias";
  }
}

}  // namespace glint::testing
