#include <gtest/gtest.h>

#include "glint/scene/Cube.hpp"

namespace glint {
namespace {

const Cube kCube(vec3(0.0), 1.0, Material{}, 3);

TEST(Cube, FacesPointOutward) {
  for (const Rectangle& f : kCube.Faces()) {
    const vec3 centre = f.PointFromUV(0.5, 0.5);
    EXPECT_GT(glm::dot(f.Normal(), centre - vec3(0.5)), 0.49);
  }
}

TEST(Cube, HitFromOutside) {
  Hit hit;
  ASSERT_TRUE(kCube.Intersect(vec3(0.5, 0.5, 5.0), vec3(0, 0, -1), kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 4.0);
  EXPECT_EQ(hit.normal, vec3(0, 0, 1));
  EXPECT_EQ(hit.object, 3);
}

TEST(Cube, HitFromInside) {
  Hit hit;
  ASSERT_TRUE(kCube.Intersect(vec3(0.5, 0.5, 0.5), vec3(1, 0, 0), kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 0.5);
  EXPECT_EQ(hit.normal, vec3(1, 0, 0));
}

TEST(Cube, MissAndBehind) {
  Hit hit;
  EXPECT_FALSE(kCube.Intersect(vec3(1.5, 0.5, 5.0), vec3(0, 0, -1), kInfinity, hit));
  EXPECT_FALSE(kCube.Intersect(vec3(0.5, 0.5, 5.0), vec3(0, 0, 1), kInfinity, hit));
  EXPECT_FALSE(kCube.IntersectsSegment(vec3(0.5, 0.5, 5.0), vec3(0, 0, -3.5)));
}

TEST(Cube, RayAlongAnEdgeHitsTheFaceItMeets) {
  // Along the edge x = 0, y = 1: the ray lies in two face planes and meets the front
  // face exactly at its corner. It must not slip through.
  Hit hit;
  ASSERT_TRUE(kCube.Intersect(vec3(0.0, 1.0, 5.0), vec3(0, 0, -1), kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 4.0);
  EXPECT_EQ(hit.normal, vec3(0, 0, 1));
  // The same from inside, along the edge x = 0, y = 0.
  ASSERT_TRUE(kCube.Intersect(vec3(0.0, 0.0, 0.5), vec3(0, 0, 1), kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 0.5);
}

TEST(Cube, RayAcrossAFaceEdgeHitsOneOfTheTwoFaces) {
  // Aimed at the edge between the top and front faces at 45 degrees.
  Hit hit;
  const vec3 d = glm::normalize(vec3(0, -1, -1));
  ASSERT_TRUE(kCube.Intersect(vec3(0.5, 2.0, 2.0), d, kInfinity, hit));
  EXPECT_NEAR(hit.t, std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(hit.normal == vec3(0, 1, 0) || hit.normal == vec3(0, 0, 1));
}

TEST(Cube, RayThroughACorner) {
  Hit hit;
  const vec3 d = glm::normalize(vec3(1, 1, 1));
  ASSERT_TRUE(kCube.Intersect(vec3(-1.0), d, kInfinity, hit));
  EXPECT_NEAR(hit.t, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(glm::length(hit.point), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(hit.normal), 1.0, 1e-15);
  EXPECT_LT(glm::dot(hit.normal, d), 0.0);
  // And out of the opposite corner from inside.
  ASSERT_TRUE(kCube.Intersect(vec3(0.5), d, kInfinity, hit));
  EXPECT_NEAR(glm::length(hit.point - vec3(1.0)), 0.0, 1e-12);
}

TEST(Cube, RayInAFacePlaneOutsideTheCubeMisses) {
  Hit hit;
  EXPECT_FALSE(kCube.Intersect(vec3(0.0, 2.0, 0.5), vec3(1, 0, 0), kInfinity, hit));
}

}  // namespace
}  // namespace glint
