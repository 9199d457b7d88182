#include <gtest/gtest.h>

#include "glint/scene/Rectangle.hpp"

namespace glint {
namespace {

const Rectangle kSquare(vec3(0.0), vec3(2, 0, 0), vec3(0, 1, 0));

TEST(Rectangle, NormalAndArea) {
  EXPECT_EQ(kSquare.Normal(), vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(kSquare.Area(), 2.0);
}

TEST(Rectangle, HitsInsideFromBothSides) {
  double t = 0;
  EXPECT_TRUE(kSquare.Intersect(vec3(1.0, 0.5, 3.0), vec3(0, 0, -1), kInfinity, t));
  EXPECT_DOUBLE_EQ(t, 3.0);
  EXPECT_TRUE(kSquare.Intersect(vec3(1.0, 0.5, -3.0), vec3(0, 0, 1), kInfinity, t));
  EXPECT_DOUBLE_EQ(t, 3.0);
}

TEST(Rectangle, BoundariesAreClosedAndTight) {
  double t = 0;
  const vec3 down(0, 0, -1);
  EXPECT_TRUE(kSquare.Intersect(vec3(0.0, 0.5, 1.0), down, kInfinity, t));
  EXPECT_TRUE(kSquare.Intersect(vec3(2.0, 0.5, 1.0), down, kInfinity, t));
  EXPECT_TRUE(kSquare.Intersect(vec3(1.0, 1.0, 1.0), down, kInfinity, t));
  EXPECT_TRUE(kSquare.Intersect(vec3(2.0, 1.0, 1.0), down, kInfinity, t));
  EXPECT_FALSE(kSquare.Intersect(vec3(-1e-9, 0.5, 1.0), down, kInfinity, t));
  EXPECT_FALSE(kSquare.Intersect(vec3(2.0 + 1e-9, 0.5, 1.0), down, kInfinity, t));
  EXPECT_FALSE(kSquare.Intersect(vec3(1.0, 1.0 + 1e-9, 1.0), down, kInfinity, t));
  EXPECT_FALSE(kSquare.Intersect(vec3(1.0, -1e-9, 1.0), down, kInfinity, t));
}

TEST(Rectangle, ParallelBehindAndBeyondTMaxMiss) {
  double t = 0;
  EXPECT_FALSE(kSquare.Intersect(vec3(1.0, 0.5, 0.0), vec3(1, 0, 0), kInfinity, t));
  EXPECT_FALSE(kSquare.Intersect(vec3(1.0, 0.5, 1.0), vec3(0, 0, 1), kInfinity, t));
  EXPECT_FALSE(kSquare.Intersect(vec3(1.0, 0.5, 1.0), vec3(0, 0, -1), 0.999, t));
}

TEST(Rectangle, PointAtLiesInThePlane) {
  const Rectangle tilted(vec3(0.1, 0.2, 0.3), vec3(0.3, 0.1, 0.0), vec3(-0.1, 0.3, 0.2));
  const vec3 o(0.7, 2.1, 1.3);
  const vec3 target = tilted.PointFromUV(0.37, 0.61);
  const vec3 d = glm::normalize(target - o);
  double t = 0;
  ASSERT_TRUE(tilted.Intersect(o, d, kInfinity, t));
  const vec3 p = tilted.PointAt(o, d, t);
  EXPECT_NEAR(glm::dot(p - tilted.Corner(), tilted.Normal()), 0.0, 1e-16);
  EXPECT_NEAR(glm::length(p - target), 0.0, 1e-14);
}

}  // namespace
}  // namespace glint
