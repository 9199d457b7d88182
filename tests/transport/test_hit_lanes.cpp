// HitLanes: the closest hit of rays from any origin found in SIMD lanes is
// Scene::Intersect's, to the bit (distance, point, normal, object, material), on every
// target this CPU runs, for the rays an integrator spawns (mirror reflections from every
// surface the camera sees, rays from random points of the room, rays towards the light,
// the cube's and the spheres' insides), and for the rare cases it hands back (a direction
// component exactly 0, an origin outside the room).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/transport/HitLanes.hpp"
#include "support/LaneTesting.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::SameBits;

struct Counts {
  int compared = 0;
  int rare = 0;
  int objects = 0;  // hits on a sphere, a cube or the light
  int escaped = 0;  // out through the open front
};

vec3 UnitDirection(Pcg32& rng) {
  const double z = 2.0 * rng.Uniform() - 1.0;
  const double phi = 2.0 * kPi * rng.Uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// A ray of kind `kind`: 0-3 a camera ray's mirror reflection, offset as the integrators
// offset it; 4 a random point of the room towards a random direction; 5 towards the
// light's centre; 6 a direction with one component exactly 0; 7 from outside the room.
void RayOfKind(const Scene& scene, const Pinhole& camera, int kind, Pcg32& rng, vec3& o, vec3& d) {
  const vec3 lo = scene.wall.Position();
  const vec3 size = scene.wall.MaxCorner() - lo;
  const vec3 inside = lo + vec3(rng.Uniform(), rng.Uniform(), rng.Uniform()) * size;
  if (kind <= 3) {
    const vec3 e = camera.DirectionThrough(64.0 * rng.Uniform(), 64.0 * rng.Uniform());
    Hit hit;
    if (scene.Intersect(camera.Eye(), e, hit, true) && !hit.light) {
      d = glm::normalize(Reflect(e, hit.normal));
      o = OffsetRayOrigin(hit.point, hit.normal, d);
      return;
    }
  }
  o = inside;
  d = UnitDirection(rng);
  if (kind == 5 && scene.light) d = glm::normalize(scene.light->Shape().Centre() - o);
  if (kind == 6) {
    d[static_cast<glm::length_t>(rng.NextU32() % 3U)] = 0.0;
    d = glm::normalize(d);
  }
  if (kind == 7) o.z = scene.wall.MaxCorner().z + 0.5;
}

Counts CompareWithScalar(const Scene& scene, SimdTarget target, bool withAreaLight, int groups) {
  const Pinhole camera = Camera::GeometryFor(scene.wall, scene.camera, 64, 64);
  const HitLanes hitLanes(scene, withAreaLight, target);
  Pcg32 rng(7, 13);
  Counts n;
  RayLanes lanes{};
  for (int g = 0; g < groups; ++g) {
    const int count = 1 + g % RayLanes::kMax;
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j) {
      vec3 o;
      vec3 d;
      RayOfKind(scene, camera, static_cast<int>(rng.NextU32() % 8U), rng, o, d);
      for (glm::length_t a = 0; a < 3; ++a) {
        lanes.start[static_cast<std::size_t>(a)][j] = o[a];
        lanes.direction[static_cast<std::size_t>(a)][j] = d[a];
      }
    }
    hitLanes.Trace(lanes, count);
    for (int i = 0; i < count; ++i) {
      const auto j = static_cast<std::size_t>(i);
      const vec3 o(lanes.start[0][j], lanes.start[1][j], lanes.start[2][j]);
      const vec3 d(lanes.direction[0][j], lanes.direction[1][j], lanes.direction[2][j]);
      Hit expected;
      const bool found = scene.Intersect(o, d, expected, withAreaLight);
      ++n.compared;
      if (lanes.closest[j] < 0.0) {
        ++n.rare;
        continue;
      }
      Hit got;
      EXPECT_EQ(hitLanes.FillHit(lanes, i, got), found);
      EXPECT_TRUE(SameBits(got.t, expected.t)) << "ray " << o.x << " " << o.y << " " << o.z;
      EXPECT_TRUE(SameBits(got.point, expected.point));
      EXPECT_TRUE(SameBits(got.normal, expected.normal));
      EXPECT_EQ(got.object, expected.object);
      EXPECT_EQ(got.material, expected.material);
      EXPECT_EQ(got.light, expected.light);
      n.objects += expected.object >= scene.wall.ObjectOf(0) + Wall::kSides || expected.light;
      n.escaped += !found;
    }
  }
  return n;
}

TEST(HitLanes, EveryTargetFindsScalarHitsBitForBit) {
  const std::vector<Scene> scenes = {
      testing::CanonicalScene(), LoadScene(testing::SourcePath("scenes/cornell-mirror.json")),
      // A sphere across the cube and one just below the light: near ties between objects.
      testing::CanonicalScene(
          {"/objects/0/center=[0.5,0.2,0.25]", "/objects/1/center=[0.5,0.83,0.5]"})};
  for (const Scene& scene : scenes) {
    for (const bool withAreaLight : {true, false}) {
      for (const SimdTarget target : SupportedSimdTargets()) {
        SCOPED_TRACE(std::string(SimdTargetName(target)) + (withAreaLight ? ", light" : ""));
        const Counts n = CompareWithScalar(scene, target, withAreaLight, 4000);
        EXPECT_GT(n.objects, n.compared / 20);  // objects were met, not walls only
        EXPECT_GT(n.escaped, n.compared / 50);  // and the open front
        // The zero components and the outside origins, an eighth each, were handed back.
        EXPECT_GT(n.rare, n.compared / 6);
        EXPECT_LT(n.rare, n.compared / 3);
      }
    }
  }
}

}  // namespace
}  // namespace glint
