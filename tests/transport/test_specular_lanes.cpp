// SpecularLanes: the mirror direction, and CrossDielectric's refracted direction and
// Fresnel reflectance, found in SIMD lanes are the scalar ones, to the bit, on every
// target this CPU runs: rays entering and leaving glass, at grazing angles, under total
// internal reflection, at normal incidence, and at index 1 (undeviated, exactly).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/transport/Fresnel.hpp"
#include "glint/transport/SpecularLanes.hpp"
#include "support/LaneTesting.hpp"

namespace glint {
namespace {

using testing::SameBits;

vec3 UnitDirection(Pcg32& rng) {
  const double z = 2.0 * rng.Uniform() - 1.0;
  const double phi = 2.0 * kPi * rng.Uniform();
  const double s = std::sqrt(1.0 - z * z);
  return {s * std::cos(phi), s * std::sin(phi), z};
}

struct Counts {
  int compared = 0;
  int total = 0;  // total internal reflections
  int fromInside = 0;
};

Counts CompareWithScalar(SimdTarget target, int groups) {
  const SpecularLanes lanes(target);
  Pcg32 rng(3, 29);
  Counts n;
  SpecularLaneData data;
  for (int g = 0; g < groups; ++g) {
    const int count = 1 + g % RayLanes::kMax;
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      const vec3 normal = UnitDirection(rng);
      vec3 d = UnitDirection(rng);
      const int kind = static_cast<int>(rng.NextU32() % 6U);
      if (kind == 0)
        d = glm::normalize(d - glm::dot(d, normal) * normal + 1e-9 * normal);  // grazing
      if (kind == 1) d = -normal;                                              // normal incidence
      const double ior = kind == 2 ? 1.0 : (kind == 3 ? 2.4 : 1.5);
      for (std::size_t a = 0; a < 3; ++a) {
        const auto c = static_cast<glm::length_t>(a);
        data.direction[a][j] = d[c];
        data.normal[a][j] = normal[c];
      }
      data.ior[j] = ior;
    }
    lanes.Find(data, count);
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      const vec3 d(data.direction[0][j], data.direction[1][j], data.direction[2][j]);
      const vec3 normal(data.normal[0][j], data.normal[1][j], data.normal[2][j]);
      const vec3 mirror(data.mirror[0][j], data.mirror[1][j], data.mirror[2][j]);
      EXPECT_TRUE(SameBits(mirror, glm::normalize(Reflect(d, normal))));
      const DielectricInterface glass = CrossDielectric(d, normal, data.ior[j]);
      EXPECT_TRUE(SameBits(data.reflectance[j], glass.reflectance));
      EXPECT_EQ(data.refracts[j] != 0.0, glass.refracted.has_value());
      if (glass.refracted) {
        const vec3 t(data.refracted[0][j], data.refracted[1][j], data.refracted[2][j]);
        EXPECT_TRUE(SameBits(t, *glass.refracted)) << "ior " << data.ior[j];
      }
      ++n.compared;
      n.total += !glass.refracted.has_value();
      n.fromInside += glm::dot(d, normal) > 0.0;
    }
  }
  return n;
}

TEST(SpecularLanes, EveryTargetFindsScalarDirectionsBitForBit) {
  for (const SimdTarget target : SupportedSimdTargets()) {
    SCOPED_TRACE(SimdTargetName(target));
    const Counts n = CompareWithScalar(target, 4000);
    EXPECT_GT(n.total, n.compared / 20);      // total internal reflection was met
    EXPECT_GT(n.fromInside, n.compared / 5);  // and rays from inside
  }
}

}  // namespace
}  // namespace glint
