// The path from x to y by one reflection off a mirror sphere: the law of reflection at
// the point found, its existence against a search of the whole sphere, the beam spread
// against finite differences of the traced reflection, and the cases where it fails.
#include <gtest/gtest.h>

#include "glint/sampling/Rng.hpp"
#include "glint/transport/SphereReflection.hpp"

namespace glint {
namespace {

const vec3 kCentre(0.22, 0.18, 0.40);  // O1 of the canonical scene
constexpr double kRadius = 0.18;

vec3 RandomPointOutside(Pcg32& rng, double margin = 0.0) {
  for (;;) {
    const vec3 p(rng.Uniform(), rng.Uniform(), rng.Uniform());
    if (glm::length(p - kCentre) > kRadius + margin) return p;
  }
}

vec3 RandomLightPoint(Pcg32& rng) {
  return {5.0 / 12.0 + rng.Uniform() / 6.0, 1.0, 5.0 / 12.0 + rng.Uniform() / 6.0};
}

// Where the ray from o along unit d first meets the sphere, if it does.
std::optional<vec3> HitSphere(vec3 o, vec3 d) {
  const vec3 f = o - kCentre;
  const double b = glm::dot(f, d);
  const double disc = b * b - (glm::dot(f, f) - kRadius * kRadius);
  if (disc < 0.0) return std::nullopt;
  return o + (-b - std::sqrt(disc)) * d;
}

TEST(SphereReflection, ThePointObeysTheLawOfReflection) {
  Pcg32 rng(1, 2);
  int found = 0;
  for (int i = 0; i < 20000; ++i) {
    const vec3 x = RandomPointOutside(rng);
    const vec3 y = RandomLightPoint(rng);
    const std::optional<SphereReflection> r = ReflectOffSphere(kCentre, kRadius, x, y);
    if (!r) continue;
    ++found;
    const vec3 toX = (x - r->point) / r->toX;
    const vec3 toY = (y - r->point) / r->toY;
    ASSERT_NEAR(glm::length(r->point - kCentre), kRadius, 1e-14);
    ASSERT_NEAR(glm::length(r->normal), 1.0, 1e-14);
    ASSERT_NEAR(glm::length(x - r->point), r->toX, 1e-13);
    ASSERT_NEAR(glm::length(y - r->point), r->toY, 1e-13);
    // Equal angles on either side of the normal, in one plane: the reflection of the
    // direction to x is the direction to y (the solver stops within about 1e-9 radians).
    ASSERT_NEAR(glm::dot(toX, r->normal), r->cosTheta, 1e-12);
    ASSERT_NEAR(glm::dot(toY, r->normal), r->cosTheta, 1e-8);
    ASSERT_LT(glm::length(Reflect(-toX, r->normal) - toY), 1e-8);
    ASSERT_GT(r->cosTheta, 0.0);
  }
  EXPECT_GT(found, 15000);
}

// A dense search of the sphere for points where the law nearly holds and both x and y
// see the point: the solver finds a reflection exactly when there is one, and the same.
TEST(SphereReflection, FindsTheReflectionExactlyWhenASearchOfTheSphereDoes) {
  Pcg32 rng(3, 4);
  constexpr int kTheta = 600;
  constexpr int kPhi = 1200;
  int withPoint = 0;
  for (int i = 0; i < 60; ++i) {
    const vec3 x = RandomPointOutside(rng, 0.01);
    const vec3 y = RandomLightPoint(rng);
    double best = 1e9;
    vec3 bestPoint(0.0);
    for (int a = 0; a < kTheta; ++a) {
      const double theta = kPi * (a + 0.5) / kTheta;
      for (int b = 0; b < kPhi; ++b) {
        const double phi = 2.0 * kPi * (b + 0.5) / kPhi;
        const vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi));
        const vec3 m = kCentre + kRadius * n;
        const vec3 toX = glm::normalize(x - m);
        const vec3 toY = glm::normalize(y - m);
        if (glm::dot(toX, n) <= 0.0 || glm::dot(toY, n) <= 0.0) continue;
        const double residual = glm::length(glm::normalize(toX + toY) - n);
        if (residual < best) {
          best = residual;
          bestPoint = m;
        }
      }
    }
    const std::optional<SphereReflection> r = ReflectOffSphere(kCentre, kRadius, x, y);
    // A grid step is 0.3 degrees: a true reflection leaves a residual below 0.01.
    EXPECT_EQ(r.has_value(), best < 0.01) << "case " << i << ", best residual " << best;
    if (r && best < 0.01) {
      EXPECT_LT(glm::length(r->point - bestPoint), 0.01 * kRadius) << "case " << i;
      ++withPoint;
    }
  }
  EXPECT_GT(withPoint, 40);
}

// spread = dA_perp(y) / d omega(x): trace a small square of directions around x -> m,
// reflect each off the sphere, and measure the patch it lands on in the plane through y
// perpendicular to the reflected ray.
TEST(SphereReflection, SpreadIsTheTracedBeamsAreaPerSolidAngle) {
  Pcg32 rng(5, 6);
  int checked = 0;
  double worst = 0.0;
  for (int i = 0; i < 400 && checked < 200; ++i) {
    const vec3 x = RandomPointOutside(rng, 0.02);
    const vec3 y = RandomLightPoint(rng);
    const std::optional<SphereReflection> r = ReflectOffSphere(kCentre, kRadius, x, y);
    if (!r || r->cosTheta < 0.05) continue;
    const vec3 w0 = (r->point - x) / r->toX;
    const vec3 axis = Reflect(w0, r->normal);
    const vec3 u = glm::normalize(glm::cross(w0, vec3(0.3, 1.0, 0.1)));
    const vec3 v = glm::cross(w0, u);
    const auto land = [&](double du, double dv) {
      const vec3 d = glm::normalize(w0 + du * u + dv * v);
      const vec3 m = *HitSphere(x, d);
      const vec3 reflected = Reflect(d, (m - kCentre) / kRadius);
      return m + (glm::dot(y - m, axis) / glm::dot(reflected, axis)) * reflected;
    };
    constexpr double kEps = 1e-6;
    const vec3 o = land(0.0, 0.0);
    const double area = glm::length(glm::cross(land(kEps, 0.0) - o, land(0.0, kEps) - o));
    const double relative = std::abs(area / (kEps * kEps) / r->spread - 1.0);
    worst = std::max(worst, relative);
    ++checked;
  }
  std::printf("spread against finite differences: %d cases, largest relative difference %.2e\n",
              checked, worst);
  EXPECT_EQ(checked, 200);
  EXPECT_LT(worst, 1e-4);
}

TEST(SphereReflection, ALargeSphereSpreadsLikeAPlaneMirror) {
  // Points 0.5 above a sphere of radius 1e6: the mirror is all but flat.
  const double big = 1e6;
  const vec3 centre(0.0, -big, 0.0);
  const vec3 x(-0.3, 0.5, 0.1);
  const vec3 y(0.4, 0.7, -0.2);
  const std::optional<SphereReflection> r = ReflectOffSphere(centre, big, x, y);
  ASSERT_TRUE(r.has_value());
  const double d = r->toX + r->toY;
  EXPECT_NEAR(r->spread / (d * d), 1.0, 1e-5);
  // And the mirror image's distance: |x - y'| with y' = y reflected in the plane y = 0.
  EXPECT_NEAR(d, glm::length(x - vec3(y.x, -y.y, y.z)), 1e-5);
}

TEST(SphereReflection, NoPathWhereNoneExistsAndNothingNonFinite) {
  const auto none = [](vec3 x, vec3 y) { return !ReflectOffSphere(kCentre, kRadius, x, y); };
  EXPECT_TRUE(none(kCentre + vec3(0.0, 0.1, 0.0), vec3(0.5, 1.0, 0.5)));  // x inside
  EXPECT_TRUE(none(vec3(0.22, 0.0, 0.40), vec3(0.5, 1.0, 0.5)));          // x touches: sees no area
  // x, c and y in a line, y beyond the sphere: it hides y's side.
  EXPECT_TRUE(none(kCentre - vec3(0.0, 0.5, 0.0), kCentre + vec3(0.0, 0.8, 0.0)));
  // Opposite sides, off the line: no point of the sphere sees both.
  EXPECT_TRUE(none(kCentre + vec3(-0.3, -0.01, 0.0), kCentre + vec3(0.3, 0.01, 0.0)));

  // Points on, just off and far from the surface, tangent configurations included.
  Pcg32 rng(7, 8);
  int finite = 0;
  for (int i = 0; i < 200000; ++i) {
    const auto near = [&] {
      const vec3 d =
          glm::normalize(vec3(rng.Uniform() - 0.5, rng.Uniform() - 0.5, rng.Uniform() - 0.5));
      const double scale = std::pow(10.0, -16.0 * rng.Uniform());
      return kCentre + kRadius * (1.0 + scale) * d;
    };
    const vec3 x = i % 2 == 0 ? near() : RandomPointOutside(rng);
    const vec3 y = i % 3 == 0 ? near() : RandomLightPoint(rng);
    const std::optional<SphereReflection> r = ReflectOffSphere(kCentre, kRadius, x, y);
    if (!r) continue;
    ASSERT_TRUE(IsFinite(r->point) && std::isfinite(r->spread) && r->spread > 0.0 &&
                r->cosTheta > 0.0 && r->cosTheta <= 1.0)
        << "x (" << x.x << ", " << x.y << ", " << x.z << ")";
    ++finite;
  }
  EXPECT_GT(finite, 10000);
}

}  // namespace
}  // namespace glint
