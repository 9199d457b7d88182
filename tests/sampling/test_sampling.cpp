// Chi-square tests of every sampling routine against its density.
#include <gtest/gtest.h>

#include "glint/sampling/Rng.hpp"
#include "glint/transport/Phong.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::ChiSquareResult;
using testing::DirectionalChiSquare;
using testing::SidakAlpha;

constexpr double kFamilyAlpha = 0.01;

void ExpectFits(const ChiSquareResult& r, double alpha, const std::string& what) {
  EXPECT_TRUE(r.failure.empty()) << what << ": " << r.failure;
  EXPECT_GT(r.pValue, alpha) << what << ": chi^2 = " << r.statistic << " with " << r.dof
                             << " degrees of freedom, p = " << r.pValue;
}

vec3 IncidentAt(double degrees) {  // travelling down onto the plane z = 0
  const double th = degrees * kPi / 180.0;
  return {std::sin(th), 0.0, -std::cos(th)};
}

const double kPhongExponents[] = {1.0, 10.0, 100.0, 1000.0};
const double kIncidences[] = {0.0, 30.0, 60.0, 85.0};

TEST(Sampling, PhongLobeMatchesItsPdf) {
  const double alpha = SidakAlpha(kFamilyAlpha, 16);
  const vec3 n(0, 0, 1);
  for (double exponent : kPhongExponents) {
    for (double incidence : kIncidences) {
      Material m;
      m.type = MaterialType::Phong;
      m.reflectance = Colour(1.0);
      m.exponent = exponent;
      const vec3 d = IncidentAt(incidence);
      DirectionalChiSquare test;
      test.axis = Reflect(d, n);  // bins around the lobe's axis, where its mass is
      test.cosMin = std::pow(1e-3, 1.0 / (exponent + 1.0));  // 99.9% of the mass above
      const ChiSquareResult r = test.Run(
          [&](Pcg32& rng) { return SamplePhong(m, d, n, rng.Uniform(), rng.Uniform()).direction; },
          [&](vec3 psi) { return PhongPdf(m, d, n, psi); }, 500000, 1);
      ExpectFits(r, alpha,
                 "n = " + std::to_string(exponent) + ", incidence " + std::to_string(incidence));
    }
  }
}

TEST(Sampling, PhongSamplerReportsTheDensityItSamplesWith) {
  // SamplePhong takes the density from its own u1, not from a second power; it must
  // agree with PhongPdf of the direction it returns, for whole and fractional n.
  for (const double exponent : {0.0, 0.5, 1.0, 37.0, 100.0, 1e4}) {
    Material m;
    m.exponent = exponent;
    Pcg32 rng(2, 3);
    for (int i = 0; i < 1000; ++i) {
      const vec3 d = IncidentAt(40.0);
      const PhongSample s = SamplePhong(m, d, vec3(0, 0, 1), rng.Uniform(), rng.Uniform());
      ASSERT_NEAR(s.pdf, PhongPdf(m, d, vec3(0, 0, 1), s.direction), 1e-9 * s.pdf)
          << "n = " << exponent;
      ASSERT_NEAR(glm::length(s.direction), 1.0, 1e-14);
    }
  }
}

TEST(Sampling, CosinePowerAgreesWithPow) {
  Pcg32 rng(5, 6);
  // Repeated squaring is within n ulp of the correctly rounded power.
  for (const double n :
       {0.0, 1.0, 2.0, 3.0, 7.0, 100.0, 101.0, 1023.0, 1024.0, 1025.0, 65535.0, 0.5, 37.25, 2e6}) {
    const double tolerance = (std::min(n, 1024.0) + 1.0) * 0x1p-52;
    for (int i = 0; i < 1000; ++i) {
      const double c = i == 0 ? 1.0 : rng.Uniform();
      const double expected = std::pow(c, n);
      ASSERT_NEAR(CosinePower(c, n), expected, tolerance * expected) << c << "^" << n;
    }
    EXPECT_EQ(CosinePower(0.0, n), n == 0.0 ? 1.0 : 0.0) << "0^" << n;
  }
}

TEST(Sampling, EvaluatePhongEqualsBrdfAndPdf) {
  Pcg32 rng(3, 9);
  for (const double exponent : {0.0, 1.0, 100.0, 1e5}) {
    Material m;
    m.type = MaterialType::Phong;
    m.reflectance = Colour(0.9, 0.5, 0.2);
    m.exponent = exponent;
    for (int i = 0; i < 20000; ++i) {
      const vec3 n = glm::normalize(vec3(rng.Uniform() - 0.5, 1.0, rng.Uniform() - 0.5));
      const vec3 d = glm::normalize(vec3(rng.Uniform() - 0.5, -rng.Uniform(), rng.Uniform() - 0.5));
      const vec3 psi = glm::normalize(
          vec3(2.0 * rng.Uniform() - 1.0, 2.0 * rng.Uniform() - 1.0, 2.0 * rng.Uniform() - 1.0));
      const PhongValue v = EvaluatePhong(m, d, n, psi);
      ASSERT_EQ(v.f, PhongBrdf(m, d, n, psi));
      ASSERT_EQ(v.pdf, PhongPdf(m, d, n, psi));
    }
  }
}

TEST(Sampling, CosineHemisphereMatchesItsPdf) {
  const double alpha = SidakAlpha(kFamilyAlpha, 2);
  for (const vec3 normal : {vec3(0, 0, 1), glm::normalize(vec3(0.3, -0.8, 0.2))}) {
    const Frame f = Frame::FromZ(normal);
    DirectionalChiSquare test;
    test.axis = normal;
    test.cosMin = 0.0;
    const ChiSquareResult r = test.Run(
        [&](Pcg32& rng) { return f.ToWorld(SampleCosineHemisphere(rng.Uniform(), rng.Uniform())); },
        [&](vec3 w) { return CosineHemispherePdf(glm::dot(w, normal)); }, 500000, 2);
    ExpectFits(r, alpha, "cosine hemisphere");
  }
}

TEST(Sampling, LightSamplingMatchesItsSolidAnglePdf) {
  const Scene scene = testing::CanonicalScene();
  const Light& light = *scene.light;
  const vec3 points[] = {vec3(0.5, 0.0, 0.5), vec3(0.1, 0.3, 0.9), vec3(0.95, 0.9, 0.05)};
  const double alpha = SidakAlpha(kFamilyAlpha, 3);
  for (const vec3 p : points) {
    const vec3 centre = light.SamplePoint(0.5, 0.5);
    DirectionalChiSquare test;
    test.axis = glm::normalize(centre - p);
    double cosMin = 1.0;
    for (double u : {0.0, 1.0}) {
      for (double v : {0.0, 1.0}) {
        cosMin = std::min(cosMin, glm::dot(test.axis, glm::normalize(light.SamplePoint(u, v) - p)));
      }
    }
    test.cosMin = cosMin - 0.1 * (1.0 - cosMin);
    test.nCos = 16;
    test.nPhi = 24;
    test.sub = 48;  // the density jumps at the light's edges: integrate finely
    const ChiSquareResult r =
        test.Run([&](Pcg32& rng) { return light.SampleLi(p, rng.Uniform(), rng.Uniform()).wi; },
                 [&](vec3 w) {
                   double t = 0.0;
                   if (!light.Shape().Intersect(p, w, kInfinity, t)) return 0.0;
                   return light.PdfLi(p, p + t * w);
                 },
                 200000, 3);
    ExpectFits(r, alpha,
               "light from (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
                   std::to_string(p.z) + ")");
  }
}

TEST(Sampling, ChiSquareRejectsAWrongPdf) {
  // The test has power: a Phong sampler checked against the density of exponent n + 2
  // (a few percent off) must fail.
  Material m;
  m.exponent = 20.0;
  Material wrong = m;
  wrong.exponent = 22.0;
  const vec3 d = IncidentAt(30.0);
  const vec3 n(0, 0, 1);
  DirectionalChiSquare test;
  test.axis = Reflect(d, n);
  test.cosMin = std::pow(1e-3, 1.0 / 21.0);
  const ChiSquareResult r = test.Run(
      [&](Pcg32& rng) { return SamplePhong(m, d, n, rng.Uniform(), rng.Uniform()).direction; },
      [&](vec3 psi) { return PhongPdf(wrong, d, n, psi); }, 500000, 4);
  EXPECT_LT(r.pValue, 1e-6);
}

TEST(Statistics, GammaQKnownValues) {
  // Q(1, x) = exp(-x); Q(dof/2, x/2) for chi^2 with 2 dof is exp(-x/2).
  EXPECT_NEAR(testing::GammaQ(1.0, 2.0), std::exp(-2.0), 1e-14);
  EXPECT_NEAR(testing::GammaQ(1.0, 0.3), std::exp(-0.3), 1e-14);
  // Q(0.5, x) = erfc(sqrt(x)).
  EXPECT_NEAR(testing::GammaQ(0.5, 1.7), std::erfc(std::sqrt(1.7)), 1e-13);
  EXPECT_NEAR(testing::GammaQ(0.5, 0.2), std::erfc(std::sqrt(0.2)), 1e-13);
  // The median of chi^2 with 100 dof is about 99.334.
  EXPECT_NEAR(testing::GammaQ(50.0, 99.334 / 2.0), 0.5, 1e-4);
}

}  // namespace
}  // namespace glint
