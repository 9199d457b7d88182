#include "glint/core/SinCos.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "glint/sampling/Rng.hpp"

namespace glint {
namespace {

// The exact values, to about 1e-19: long double's 64-bit significand on x86-64.
long double ExactSin(double u) {
  return std::sin(6.283185307179586476925286766559L * static_cast<long double>(u));
}
long double ExactCos(double u) {
  return std::cos(6.283185307179586476925286766559L * static_cast<long double>(u));
}
double ErrorAt(double u) {
  const SinCos sc = SinCosTurns(u);
  return static_cast<double>(
      std::max(std::abs(sc.sin - ExactSin(u)), std::abs(sc.cos - ExactCos(u))));
}

TEST(SinCosTurns, WithinTheBoundOfTheExactValuesOverATurn) {
  // A sampler's azimuths: uniforms in [0, 1), and every 1/8 turn's neighbourhood, where
  // the reduction changes quarter or the series reaches its widest argument, pi/4.
  Pcg32 rng(7, 11);
  double worst = 0.0;
  for (int i = 0; i < 1000000; ++i) worst = std::max(worst, ErrorAt(rng.Uniform()));
  for (int k = 0; k <= 8; ++k) {
    for (const double d : {-1e-3, -1e-9, -0x1.0p-53, 0.0, 0x1.0p-53, 1e-9, 1e-3}) {
      worst = std::max(worst, ErrorAt(k / 8.0 + d));
    }
  }
  EXPECT_LE(worst, 2.5e-16);
}

TEST(SinCosTurns, AsAccurateAsLibmsSinCosOfTwoPiU) {
  // libm's error includes 2 pi u's rounding, up to 2 pi 2^-53 absolute near a turn.
  Pcg32 rng(3, 5);
  double ours = 0.0;
  double libm = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double u = rng.Uniform();
    ours = std::max(ours, ErrorAt(u));
    const double phi = 2.0 * 3.14159265358979323846 * u;
    libm = std::max(libm, static_cast<double>(std::abs(std::sin(phi) - ExactSin(u))));
  }
  EXPECT_LE(ours, libm);
}

TEST(SinCosTurns, ExactAtWholeQuarterTurnsAndPeriodic) {
  const double sines[] = {0.0, 1.0, 0.0, -1.0};
  const double cosines[] = {1.0, 0.0, -1.0, 0.0};
  for (int k = -8; k <= 8; ++k) {
    const SinCos sc = SinCosTurns(k / 4.0);
    EXPECT_EQ(sc.sin, sines[(k + 8) % 4]) << "k = " << k;
    EXPECT_EQ(sc.cos, cosines[(k + 8) % 4]) << "k = " << k;
  }
  // Whole turns away, the same angle: exactly, since the reduction is exact (for u + turns
  // that is exact too: multiples of 2^-10 here).
  for (const double u : {103.0 / 1024.0, 307.0 / 1024.0, 625.0 / 1024.0, 993.0 / 1024.0}) {
    for (const double turns : {-3.0, -1.0, 1.0, 5.0}) {
      EXPECT_EQ(SinCosTurns(u + turns).sin, SinCosTurns(u).sin) << u << " + " << turns;
      EXPECT_EQ(SinCosTurns(u + turns).cos, SinCosTurns(u).cos) << u << " + " << turns;
    }
  }
}

TEST(SinCosTurns, OnTheUnitCircle) {
  Pcg32 rng(1, 2);
  for (int i = 0; i < 100000; ++i) {
    const SinCos sc = SinCosTurns(rng.Uniform());
    ASSERT_NEAR(sc.sin * sc.sin + sc.cos * sc.cos, 1.0, 4.5e-16);
  }
}

}  // namespace
}  // namespace glint
