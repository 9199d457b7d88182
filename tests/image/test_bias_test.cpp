// The bias test behind `glint compare`, on images whose noise is known: independent
// noisy copies of one image agree, a 1% scale does not, and the limits are the normal
// distribution's.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/image/BiasTest.hpp"
#include "glint/sampling/Rng.hpp"

namespace glint {
namespace {

// A smooth image plus Gaussian noise of relative size `noise` (Box-Muller), times scale.
Image Noisy(int size, double noise, double scale, std::uint64_t seed) {
  Pcg32 rng(seed, 3);
  Image image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      Colour c(0.2 + 0.5 * x / size, 0.3 + 0.4 * y / size, 0.5);
      for (int k = 0; k < 3; ++k) {
        const double g =
            std::sqrt(-2.0 * std::log(1.0 - rng.Uniform())) * std::cos(2.0 * kPi * rng.Uniform());
        c[k] *= scale * (1.0 + noise * g);
      }
      image.At(x, y) = c;
    }
  }
  return image;
}

TEST(BiasTest, NormalQuantilesAreTheKnownOnes) {
  EXPECT_NEAR(NormalQuantileTwoSided(0.05), 1.959964, 1e-5);
  EXPECT_NEAR(NormalQuantileTwoSided(6.334248e-5), 4.0, 1e-5);
}

TEST(BiasTest, IndependentCopiesAgreeAndAOnePercentScaleDoesNot) {
  int agreed = 0;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const Image a = Noisy(64, 0.05, 1.0, 4 * seed);
    const Image b = Noisy(64, 0.05, 1.0, 4 * seed + 1);
    const Image r1 = Noisy(64, 0.05, 1.0, 4 * seed + 2);
    const Image r2 = Noisy(64, 0.05, 1.0, 4 * seed + 3);
    const BiasVerdict v = TestBias(a, b, r1, &r2);
    agreed += v.agree ? 1 : 0;
    EXPECT_EQ(v.blockTests, 48);
    EXPECT_NEAR(v.blockLimit, 4.26, 0.01);
    const Image a2 = Noisy(64, 0.05, 1.01, 4 * seed);
    const Image b2 = Noisy(64, 0.05, 1.01, 4 * seed + 1);
    EXPECT_FALSE(TestBias(a2, b2, r1, &r2).agree) << "seed " << seed;
  }
  EXPECT_GE(agreed, 19);  // a 0.001 family level, plus the 4-sigma mean: 20 of 20 expected
}

TEST(BiasTest, ZOfUnbiasedCopiesHasUnitVariance) {
  // Each z uses its own images' spread: over 400 independent sets its RMS is 1 within
  // 3.5% (one standard error), so a standard error off by a factor (the reference's noise
  // left out: 1.22, a wrong factor 2: 0.5) shows.
  double sum2 = 0.0;
  constexpr int kSets = 400;
  for (std::uint64_t seed = 0; seed < kSets; ++seed) {
    const Image a = Noisy(16, 0.1, 1.0, 4 * seed + 1000);
    const Image b = Noisy(16, 0.1, 1.0, 4 * seed + 1001);
    const Image r1 = Noisy(16, 0.1, 1.0, 4 * seed + 1002);
    const Image r2 = Noisy(16, 0.1, 1.0, 4 * seed + 1003);
    const double z = TestBias(a, b, r1, &r2).meanZ;
    sum2 += z * z;
  }
  const double rms = std::sqrt(sum2 / kSets);
  EXPECT_NEAR(rms, 1.0, 0.11);
}

TEST(BiasTest, NoiselessImagesAgreeOnlyWhenEqual) {
  const Image a = Noisy(32, 0.0, 1.0, 1);
  EXPECT_TRUE(TestBias(a, a, a, nullptr).agree);
  const Image b = Noisy(32, 0.0, 1.0001, 1);
  const BiasVerdict v = TestBias(b, b, a, nullptr);
  EXPECT_FALSE(v.agree);
  EXPECT_TRUE(std::isinf(v.meanZ));
}

TEST(BiasTest, RefusesImagesOfDifferentSizes) {
  EXPECT_THROW(TestBias(Image(8, 8), Image(8, 8), Image(8, 4), nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace glint
