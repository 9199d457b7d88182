#include "glint/core/Format.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

namespace glint {
namespace {

TEST(Format, ShortestTextThatReadsBackExactly) {
  EXPECT_EQ(FormatNumber(0.5), "0.5");
  EXPECT_EQ(FormatNumber(1.0), "1");
  EXPECT_EQ(FormatNumber(-0.18), "-0.18");
  EXPECT_EQ(FormatNumber(1e6), "1000000");
  EXPECT_EQ(FormatNumber(0.0), "0");
  EXPECT_EQ(FormatNumber(1e-9), "1e-09");
  EXPECT_EQ(FormatNumber(1.0 / 3.0), "0.3333333333333333");
  // Every double reads back as itself.
  for (const double x : {0.1, 2.0 / 3.0, 123456.789, 5e-5, 1e300, -7.25e-12,
                         std::numeric_limits<double>::denorm_min()}) {
    EXPECT_EQ(std::strtod(FormatNumber(x).c_str(), nullptr), x) << FormatNumber(x);
  }
}

TEST(Format, ComputedValuesLoseTheirRoundingNoise) {
  EXPECT_EQ(FormatComputed(0.22 - 0.3), "-0.08");
  EXPECT_EQ(FormatComputed(0.4 + 0.18), "0.58");
  EXPECT_EQ(FormatComputed(0.5 + 1.0 / 3.0), "0.833333333333");
  EXPECT_EQ(FormatPoint(vec3(0.5, 0.1 + 0.2, 2.5)), "(0.5, 0.3, 2.5)");
}

}  // namespace
}  // namespace glint
