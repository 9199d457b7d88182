#include <gtest/gtest.h>

#include "glint/transport/Fresnel.hpp"

namespace glint {
namespace {

const vec3 kN(0, 0, 1);  // outward normal; the object (index n) lies at z < 0

vec3 Incident(double thetaDegrees, bool fromInside) {
  const double th = thetaDegrees * kPi / 180.0;
  const vec3 d(std::sin(th), 0.0, -std::cos(th));  // travelling toward -z (into the object)
  return fromInside ? vec3(d.x, d.y, -d.z) : d;
}

// Transmittance from the amplitude transmission coefficients, independently of F:
// T = (n2 cos_t) / (n1 cos_i) * (t_s^2 + t_p^2) / 2.
double Transmittance(double n1, double n2, double cosI, double cosT) {
  const double ts = 2 * n1 * cosI / (n1 * cosI + n2 * cosT);
  const double tp = 2 * n1 * cosI / (n2 * cosI + n1 * cosT);
  return (n2 * cosT) / (n1 * cosI) * 0.5 * (ts * ts + tp * tp);
}

TEST(Fresnel, SnellsLawBothWays) {
  for (bool inside : {false, true}) {
    const double n1 = inside ? 1.5 : 1.0;
    const double n2 = inside ? 1.0 : 1.5;
    for (double deg = 0.0; deg < 41.0; deg += 2.5) {
      const vec3 d = Incident(deg, inside);
      const std::optional<vec3> t = Refract(d, kN, 1.5);
      ASSERT_TRUE(t.has_value()) << deg;
      EXPECT_NEAR(glm::length(*t), 1.0, 1e-15);
      const double sinI = std::sin(deg * kPi / 180.0);
      const double sinT = std::sqrt(t->x * t->x + t->y * t->y);
      EXPECT_NEAR(n1 * sinI, n2 * sinT, 1e-14) << deg;
      EXPECT_NEAR(t->y, 0.0, 1e-15);  // in the plane of incidence
      EXPECT_GE(t->x * d.x, 0.0);     // on the far side of the normal
      EXPECT_GT(t->z * d.z, 0.0);     // keeps travelling through
    }
  }
}

TEST(Fresnel, ReflectanceAndTransmittanceSumToOne) {
  for (bool inside : {false, true}) {
    const double n1 = inside ? 1.5 : 1.0;
    const double n2 = inside ? 1.0 : 1.5;
    for (double deg = 0.0; deg < 89.9; deg += 1.7) {
      const vec3 d = Incident(deg, inside);
      const std::optional<vec3> t = Refract(d, kN, 1.5);
      if (!t) continue;
      const double cosI = std::cos(deg * kPi / 180.0);
      const double cosT = std::abs(t->z);
      const double f = FresnelDielectric(d, kN, 1.5);
      EXPECT_NEAR(f + Transmittance(n1, n2, cosI, cosT), 1.0, 1e-12) << deg << " " << inside;
      EXPECT_GE(f, 0.0);
      EXPECT_LE(f, 1.0);
    }
  }
}

TEST(Fresnel, NormalIncidence) {
  EXPECT_NEAR(FresnelDielectric(vec3(0, 0, -1), kN, 1.5), 0.04, 1e-15);
  EXPECT_NEAR(FresnelDielectric(vec3(0, 0, 1), kN, 1.5), 0.04, 1e-15);  // from inside
  EXPECT_NEAR(FresnelNormalIncidence(1.5), 0.04, 1e-15);
  EXPECT_NEAR(FresnelDielectric(vec3(0, 0, -1), kN, 1.3),
              ((1.3 - 1) / (1.3 + 1)) * ((1.3 - 1) / (1.3 + 1)), 1e-15);
}

TEST(Fresnel, TotalInternalReflectionPastTheCriticalAngle) {
  const double critical = std::asin(1.0 / 1.5) * 180.0 / kPi;  // 41.81 degrees
  for (double deg : {critical + 1e-6, critical + 0.1, 50.0, 70.0, 89.0, 90.0}) {
    const vec3 d = Incident(deg, true);
    EXPECT_FALSE(Refract(d, kN, 1.5).has_value()) << deg;
    EXPECT_EQ(FresnelDielectric(d, kN, 1.5), 1.0) << deg;
  }
  const vec3 below = Incident(critical - 1e-6, true);
  ASSERT_TRUE(Refract(below, kN, 1.5).has_value());
  EXPECT_LT(FresnelDielectric(below, kN, 1.5), 1.0);
  EXPECT_GT(FresnelDielectric(below, kN, 1.5), 0.9);
  // From outside there is never total internal reflection, even at grazing incidence.
  EXPECT_TRUE(Refract(Incident(89.999, false), kN, 1.5).has_value());
  EXPECT_NEAR(FresnelDielectric(Incident(90.0, false), kN, 1.5), 1.0, 1e-12);
}

TEST(Fresnel, ReciprocityAcrossTheBoundary) {
  for (double deg = 1.0; deg < 89.0; deg += 4.0) {
    const vec3 d = Incident(deg, false);
    const vec3 t = *Refract(d, kN, 1.5);
    // Reversing the refracted ray from inside sees the same reflectance.
    EXPECT_NEAR(FresnelDielectric(-t, kN, 1.5), FresnelDielectric(d, kN, 1.5), 1e-12);
    const vec3 back = *Refract(-t, kN, 1.5);
    EXPECT_NEAR(glm::length(back + d), 0.0, 1e-13);
  }
}

TEST(Fresnel, IndexOneIsInvisible) {
  for (double deg = 0.0; deg < 89.9; deg += 3.1) {
    for (bool inside : {false, true}) {
      const vec3 d = Incident(deg, inside);
      EXPECT_EQ(FresnelDielectric(d, kN, 1.0), 0.0);
      const std::optional<vec3> t = Refract(d, kN, 1.0);
      ASSERT_TRUE(t.has_value());
      EXPECT_NEAR(glm::length(*t - d), 0.0, 1e-15);
    }
  }
}

}  // namespace
}  // namespace glint
