#include <gtest/gtest.h>

#include "glint/transport/Fresnel.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::CanonicalScene;

// Traces one ray from `start` along `d` and returns the tree.
RayTree TraceOne(const Integrator& integrator, vec3 start, vec3 d, Colour* colour = nullptr) {
  RayTree tree;
  Ray ray;
  ray.start = start;
  ray.direction = glm::normalize(d);
  const std::uint32_t root = tree.Add(ray);
  Sampler sampler(Pcg32(1, 1));
  RenderStats stats;
  const Colour c = integrator.Trace(tree, root, PixelShaft{}, sampler, stats);
  if (colour) *colour = c;
  return tree;
}

TEST(Whitted, LambertianObjectIsLitDirectlyAsAWall) {
  // The top of O1, lambertian: L = rho / pi * sum over P1, P2 of I cos(theta) / r^2, and
  // no child.
  const Scene scene = LoadScene(testing::SourcePath("scenes/cornell-lambert.json"));
  const WhittedIntegrator integrator(scene, 10);
  const vec3 top(0.22, 0.36, 0.40);
  Colour c;
  const RayTree tree = TraceOne(integrator, top + vec3(0.0, 0.1, 0.0), vec3(0, -1, 0), &c);
  double expected = 0.0;
  for (const vec3 light : {vec3(0.50, 0.98, 0.50), vec3(0.02, 0.60, 0.75)}) {
    const vec3 l = light - top;
    expected += 0.9 * kInvPi * l.y / std::pow(glm::dot(l, l), 1.5);
  }
  EXPECT_EQ(tree.Size(), 1u);
  EXPECT_TRUE(tree[0].final);
  EXPECT_NEAR(tree[0].end.y, 0.36, 1e-12);
  EXPECT_NEAR(c.x, expected, 1e-9 * expected);
}

TEST(Whitted, UnshadowedWallPointMatchesTheClosedForm) {
  // One point light, no objects: L = rho / pi * I cos(theta) / r^2.
  const Scene scene = CanonicalScene(
      {"/objects=[]",
       R"(/point_lights=[{"position": [0.5, 0.9, 0.6], "intensity": [1.0, 2.0, 3.0]}])"});
  const WhittedIntegrator integrator(scene, 10);
  const vec3 eye(0.5, 0.5, 2.5);
  for (const vec3 p : {vec3(0.3, 0.4, 0.0), vec3(0.9, 0.2, 0.0), vec3(0.5, 0.5, 0.0)}) {
    Colour c;
    const RayTree tree = TraceOne(integrator, eye, p - eye, &c);
    const vec3 toLight = vec3(0.5, 0.9, 0.6) - p;
    const double r2 = glm::dot(toLight, toLight);
    const double cosTheta = toLight.z / std::sqrt(r2);
    const Colour expected = vec3(0.75) * kInvPi * Colour(1, 2, 3) * cosTheta / r2;
    EXPECT_NEAR(c.x, expected.x, 1e-12 * expected.x);
    EXPECT_NEAR(c.y, expected.y, 1e-12 * expected.y);
    EXPECT_NEAR(c.z, expected.z, 1e-12 * expected.z);
    EXPECT_EQ(tree.Size(), 1u);  // walls spawn no children
    EXPECT_TRUE(tree[0].final);
    EXPECT_EQ(scene.ObjectName(tree[0].object), "W5");
  }
}

TEST(Whitted, BothLightsAddOnAWall) {
  const Scene both = CanonicalScene({"/objects=[]"});
  const Scene p1 = CanonicalScene({"/objects=[]", "/point_lights/1/intensity=[0,0,0]"});
  const Scene p2 = CanonicalScene({"/objects=[]", "/point_lights/0/intensity=[0,0,0]"});
  const vec3 eye(0.5, 0.5, 2.5);
  const vec3 d = vec3(0.6, 0.3, 0.0) - eye;
  Colour a, b, c;
  TraceOne(WhittedIntegrator(both, 10), eye, d, &a);
  TraceOne(WhittedIntegrator(p1, 10), eye, d, &b);
  TraceOne(WhittedIntegrator(p2, 10), eye, d, &c);
  EXPECT_NEAR(a.x, b.x + c.x, 1e-14);
  EXPECT_GT(b.x, 0.0);
  EXPECT_GT(c.x, 0.0);
}

// A floor point whose line to the light passes through an object's centre, seen from
// nearby: dark behind an opaque object, lit behind glass.
Colour FloorBehind(const std::string& objects, vec3 light, vec3 centre) {
  const Scene scene = CanonicalScene(
      {"/objects=" + objects, R"(/point_lights=[{"position": [)" + std::to_string(light.x) + "," +
                                  std::to_string(light.y) + "," + std::to_string(light.z) +
                                  R"(], "intensity": [1, 1, 1]}])"});
  const vec3 d = glm::normalize(centre - light);
  const vec3 floor = light + (-light.y / d.y) * d;
  const vec3 eye = floor + vec3(0.0, 0.02, 0.05);
  Colour c;
  const RayTree tree = TraceOne(WhittedIntegrator(scene, 10), eye, floor - eye, &c);
  EXPECT_EQ(scene.ObjectName(tree[0].object), "W4");
  return c;
}

TEST(Whitted, OpaqueObjectsCastShadowsGlassDoesNot) {
  const std::string mirror =
      R"([{"type": "sphere", "center": [0.22, 0.18, 0.40], "radius": 0.18, "material": "mirror",
          "reflectance": [0.9, 0.9, 0.9]}])";
  const std::string glass =
      R"([{"type": "sphere", "center": [0.74, 0.16, 0.70], "radius": 0.16, "material": "glass",
          "ior": 1.5}])";
  EXPECT_EQ(FloorBehind(mirror, vec3(0.6, 0.5, 0.4), vec3(0.22, 0.18, 0.40)), Colour(0.0));
  const Colour lit = FloorBehind("[]", vec3(0.5, 0.35, 0.7), vec3(0.74, 0.16, 0.70));
  EXPECT_GT(lit.x, 0.0);
  EXPECT_EQ(FloorBehind(glass, vec3(0.5, 0.35, 0.7), vec3(0.74, 0.16, 0.70)), lit);
}

TEST(Whitted, NodeWeightsSumToOneAndImportanceIsTheirProduct) {
  const Scene scene = CanonicalScene();
  const WhittedIntegrator integrator(scene, 10);
  const vec3 eye(0.5, 0.5, 2.5);
  const Material& glass = scene.spheres[1].GetMaterial();
  const Material& mirror = scene.spheres[0].GetMaterial();
  // At the glass sphere: kd + ks + sum of the children's weights = 1.
  const RayTree tree = TraceOne(integrator, eye, vec3(0.7, 0.2, 0.72) - eye);
  ASSERT_EQ(scene.ObjectName(tree[0].object), "O2");
  ASSERT_EQ(tree[0].childCount, 2u);
  const double sum = tree[1].weight.x + tree[2].weight.x;
  EXPECT_NEAR(glass.whittedDiffuse + glass.whittedSpecular + sum, 1.0, 1e-15);
  EXPECT_EQ(tree[1].kind, RayKind::Reflected);
  EXPECT_EQ(tree[2].kind, RayKind::Refracted);
  EXPECT_TRUE(tree[2].inside);
  EXPECT_FALSE(tree[1].inside);
  // At the mirror sphere: one child of weight (1 - kd - ks) rho.
  const RayTree m = TraceOne(integrator, eye, vec3(0.22, 0.2, 0.5) - eye);
  ASSERT_EQ(scene.ObjectName(m[0].object), "O1");
  ASSERT_EQ(m[0].childCount, 1u);
  EXPECT_NEAR(m[1].weight.x, (1.0 - mirror.whittedDiffuse - mirror.whittedSpecular) * 0.9, 1e-15);
  // Everywhere: importance = parent importance x weight.
  for (const RayTree* t : {&tree, &m}) {
    for (std::size_t i = 0; i < t->Size(); ++i) {
      const Ray& node = (*t)[static_cast<std::uint32_t>(i)];
      for (std::uint32_t k = 0; k < node.childCount; ++k) {
        const Ray& child = (*t)[node.firstChild + k];
        EXPECT_NEAR(glm::length(child.importance - node.importance * child.weight), 0.0, 1e-15);
        EXPECT_EQ(child.depth, node.depth + 1);
      }
    }
  }
}

TEST(Whitted, SmallAngleFresnelWeighsGlassByTheNormalIncidenceReflectance) {
  // The design's small-angle study (lecture 2) in Whitted mode: R0 at an oblique hit,
  // where the Fresnel equations give more.
  const Scene scene = CanonicalScene();
  const Material& glass = scene.spheres[1].GetMaterial();
  const double w = glass.WhittedChildWeight();
  const vec3 eye(0.5, 0.5, 2.5);
  const vec3 d = vec3(0.895, 0.16, 0.72) - eye;  // near O2's rim: far from normal incidence
  const RayTree exact = TraceOne(WhittedIntegrator(scene, 10), eye, d);
  const RayTree small = TraceOne(WhittedIntegrator(scene, 10, FresnelModel::SmallAngle), eye, d);
  ASSERT_EQ(scene.ObjectName(small[0].object), "O2");
  ASSERT_EQ(small[0].childCount, 2u);
  const double r0 = FresnelNormalIncidence(1.5);
  EXPECT_NEAR(small[1].weight.x, w * r0, 1e-15);
  EXPECT_NEAR(small[2].weight.x, w * (1.0 - r0), 1e-15);
  EXPECT_GT(exact[1].weight.x, 1.5 * small[1].weight.x);
}

TEST(Whitted, ColourIsLocalLightPlusWeightedChildren) {
  const Scene scene = CanonicalScene();
  const WhittedIntegrator integrator(scene, 10);
  const vec3 eye(0.5, 0.5, 2.5);
  const RayTree tree = TraceOne(integrator, eye, vec3(0.7, 0.2, 0.72) - eye);
  for (std::size_t i = 0; i < tree.Size(); ++i) {
    const Ray& node = tree[static_cast<std::uint32_t>(i)];
    Colour children(0.0);
    for (std::uint32_t k = 0; k < node.childCount; ++k) {
      children += tree[node.firstChild + k].weight * tree[node.firstChild + k].colour;
    }
    // The rest is the local term: never negative, never NaN.
    const Colour local = node.colour - children;
    EXPECT_GE(local.x, -1e-12);
    EXPECT_TRUE(IsFinite(node.colour));
    EXPECT_EQ(node.final, node.childCount == 0);
  }
}

TEST(Whitted, DepthLimitCountsRayIterations) {
  for (int limit : {1, 2, 3, 10}) {
    const Scene scene = CanonicalScene();
    const WhittedIntegrator integrator(scene, limit);
    const vec3 eye(0.5, 0.5, 2.5);
    int deepest = 0;
    for (int i = 0; i < 200; ++i) {
      // A fan of rays across the glass sphere, where trees grow deepest.
      const vec3 target(0.60 + 0.28 * i / 200.0, 0.16, 0.70);
      const RayTree tree = TraceOne(integrator, eye, target - eye);
      for (std::size_t k = 0; k < tree.Size(); ++k) {
        deepest = std::max(deepest, int(tree[static_cast<std::uint32_t>(k)].depth));
      }
    }
    EXPECT_EQ(deepest, limit - 1) << "limit " << limit;
  }
}

TEST(Whitted, GlassOfIndexOneIsInvisible) {
  // With no highlight and n = 1, a camera ray passes the sphere undeviated: its colour
  // equals that of the scene without the sphere.
  const Scene without = CanonicalScene({"/objects=[]"});
  const Scene glassOnly =
      CanonicalScene({R"(/objects=[{"type": "sphere", "center": [0.74, 0.16, 0.70], "radius": 0.16,
           "material": "glass", "ior": 1.0}])"});
  const vec3 eye(0.5, 0.5, 2.5);
  for (int i = 0; i < 50; ++i) {
    // Points of the sphere's central plane within 0.13 of its centre (radius 0.16).
    const vec3 target(0.64 + 0.2 * i / 50.0, 0.16 + 0.06 * ((i % 3) - 1), 0.70);
    Colour a, b;
    const RayTree tree = TraceOne(WhittedIntegrator(glassOnly, 10), eye, target - eye, &a);
    ASSERT_EQ(glassOnly.ObjectName(tree[0].object), "O1");  // the glass sphere, first here
    ASSERT_EQ(tree[0].childCount, 1u);                      // F = 0: no reflected child
    TraceOne(WhittedIntegrator(without, 10), eye, target - eye, &b);
    EXPECT_NEAR(a.x, b.x, 1e-6 * (1.0 + b.x)) << i;
    EXPECT_NEAR(a.y, b.y, 1e-6 * (1.0 + b.y)) << i;
  }
}

}  // namespace
}  // namespace glint
