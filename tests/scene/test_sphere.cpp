#include <gtest/gtest.h>

#include "glint/sampling/Rng.hpp"
#include "glint/scene/Sphere.hpp"

namespace glint {
namespace {

const Sphere kUnit(vec3(0.0), 1.0, Material{}, 7);

TEST(Sphere, HitFromOutside) {
  Hit hit;
  ASSERT_TRUE(kUnit.Intersect(vec3(0, 0, -5), vec3(0, 0, 1), kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 4.0);
  EXPECT_DOUBLE_EQ(hit.point.z, -1.0);
  EXPECT_DOUBLE_EQ(hit.normal.z, -1.0);
  EXPECT_EQ(hit.object, 7);
}

TEST(Sphere, HitFromInsideHasOutwardNormal) {
  Hit hit;
  ASSERT_TRUE(kUnit.Intersect(vec3(0.0), vec3(1, 0, 0), kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 1.0);
  EXPECT_DOUBLE_EQ(hit.normal.x, 1.0);  // outward: dot(d, n) > 0 tells "inside"
}

TEST(Sphere, BehindTheOriginIsAMiss) {
  Hit hit;
  EXPECT_FALSE(kUnit.Intersect(vec3(0, 0, 5), vec3(0, 0, 1), kInfinity, hit));
  EXPECT_FALSE(kUnit.IntersectsSegment(vec3(0, 0, 5), vec3(0, 0, 100)));
}

TEST(Sphere, BeyondTMaxIsAMiss) {
  Hit hit;
  EXPECT_FALSE(kUnit.Intersect(vec3(0, 0, -5), vec3(0, 0, 1), 3.9, hit));
  EXPECT_FALSE(kUnit.IntersectsSegment(vec3(0, 0, -5), vec3(0, 0, 3.9)));
}

TEST(Sphere, TangentRayIsFiniteAndNearMissesAreDecided) {
  Hit hit;
  // Exactly tangent: a hit at the tangent point or a miss are both fine; NaN is not.
  if (kUnit.Intersect(vec3(1, 0, -5), vec3(0, 0, 1), kInfinity, hit)) {
    EXPECT_TRUE(IsFinite(hit.point));
    EXPECT_NEAR(glm::length(hit.normal), 1.0, 1e-12);
    EXPECT_NEAR(hit.point.x, 1.0, 1e-6);
    EXPECT_NEAR(hit.t, 5.0, 1e-3);
  }
  EXPECT_FALSE(kUnit.Intersect(vec3(1.0 + 1e-9, 0, -5), vec3(0, 0, 1), kInfinity, hit));
  ASSERT_TRUE(kUnit.Intersect(vec3(1.0 - 1e-6, 0, -5), vec3(0, 0, 1), kInfinity, hit));
  EXPECT_TRUE(IsFinite(hit.point));
}

TEST(Sphere, HitPointsLieOnTheSurface) {
  const Sphere s(vec3(0.74, 0.16, 0.70), 0.16, Material{}, 0);
  Pcg32 rng(3, 1);
  int hits = 0;
  for (int i = 0; i < 10000; ++i) {
    const vec3 origin(rng.Uniform() * 100 - 50, rng.Uniform() * 100 - 50, 60.0);
    const vec3 target = s.Centre() + 0.2 * vec3(rng.Uniform() - 0.5, rng.Uniform() - 0.5, 0.0);
    Hit hit;
    if (!s.Intersect(origin, glm::normalize(target - origin), kInfinity, hit)) continue;
    ++hits;
    ASSERT_NEAR(glm::length(hit.point - s.Centre()), s.Radius(), 1e-15);
  }
  EXPECT_GT(hits, 5000);
}

TEST(Sphere, OffsetRayDoesNotHitItsOwnSurface) {
  Pcg32 rng(5, 2);
  for (int i = 0; i < 10000; ++i) {
    const double z = 2 * rng.Uniform() - 1;
    const double phi = 2 * kPi * rng.Uniform();
    const vec3 n(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    const vec3 p = 0.18 * n + vec3(0.22, 0.18, 0.40);
    const Sphere s(vec3(0.22, 0.18, 0.40), 0.18, Material{}, 0);
    // Leaving outward, nearly grazing: must not find the sphere again.
    const vec3 t = glm::normalize(glm::cross(n, vec3(0.3, 0.5, 0.7)));
    const vec3 out = glm::normalize(t + 1e-4 * n);
    EXPECT_FALSE(s.IntersectsSegment(OffsetRayOrigin(p, n, out), 10.0 * out));  // 10 >> 2r
    // Leaving inward: the next hit is the far side, not the start point.
    const vec3 in = glm::normalize(t - 0.5 * n);
    Hit hit;
    ASSERT_TRUE(s.Intersect(OffsetRayOrigin(p, n, in), in, kInfinity, hit));
    EXPECT_GT(hit.t, 1e-3);
  }
}

}  // namespace
}  // namespace glint
