// Stability where ray tracers usually break: index 1, extreme Phong exponents, total
// internal reflection, edges, corners, tangents, grazing rays, contact lines, shadow
// acne, and NaN/Inf in every mode. Each test pins down the right answer.
#include <gtest/gtest.h>

#include "glint/camera/Camera.hpp"
#include "glint/transport/Fresnel.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/Phong.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::CanonicalScene;
using testing::MeanAndError;

Image RenderImage(const Scene& scene, const Integrator& integrator, int size, int spp,
                  std::uint64_t seed, RenderStats* stats = nullptr) {
  Camera camera(scene.wall, scene.camera, size, size);
  RenderOptions options;
  options.raysPerPixel = spp;
  options.seed = seed;
  const RenderStats s = camera.Render(integrator, options);
  if (stats) *stats = s;
  return camera.ToImage();
}

Colour TraceOnce(const Integrator& integrator, vec3 start, vec3 d, Pcg32& rng, RayTree& tree,
                 RenderStats& stats) {
  tree.Clear();
  Ray ray;
  ray.start = start;
  ray.direction = glm::normalize(d);
  Sampler sampler(rng);
  const Colour c = integrator.Trace(tree, tree.Add(ray), PixelShaft{}, sampler, stats);
  rng = sampler.Generator();  // the test's stream goes on where the trace left it
  return c;
}

TEST(Stability, GlassOfIndexOneLeavesTheWhittedImageUnchanged) {
  // No highlight (whitted_specular 0) and n = 1: the image equals the image without O2.
  const Scene with = CanonicalScene({"/objects/1/ior=1.0", "/objects/1/whitted_specular=0"});
  const Scene without =
      CanonicalScene({R"(/objects=[{"type": "sphere", "center": [0.22, 0.18, 0.40], "radius": 0.18,
           "material": "phong", "reflectance": [0.9, 0.9, 0.9], "exponent": 100,
           "whitted_diffuse": 0.1, "whitted_specular": 0.1},
          {"type": "cube", "position": [0.42, 0.0, 0.06], "size": 0.28, "material": "phong",
           "reflectance": [0.85, 0.75, 0.45], "exponent": 100, "whitted_diffuse": 0.1,
           "whitted_specular": 0.1}])"});
  const Image a = RenderImage(with, WhittedIntegrator(with, 10), 64, 2, 3);
  const Image b = RenderImage(without, WhittedIntegrator(without, 10), 64, 2, 3);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.Pixels().size(); ++i) {
    worst = std::max(worst, MaxComponent(glm::abs(a.Pixels()[i] - b.Pixels()[i])));
  }
  EXPECT_LT(worst, 1e-9);
  // With its highlight, O2 changes only pixels it covers: never the walls around it.
  const Scene lit = CanonicalScene({"/objects/1/ior=1.0"});
  const Image c = RenderImage(lit, WhittedIntegrator(lit, 10), 64, 2, 3);
  const Camera camera(lit.wall, lit.camera, 64, 64);
  const WhittedIntegrator whitted(lit, 10);
  Pcg32 rng(1, 1);
  RayTree tree;
  RenderStats stats;
  int untouched = 0;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      bool coversO2 = false;  // some ray tree of the pixel meets the sphere, at any depth
      for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        for (double v : {0.0, 0.25, 0.5, 0.75, 1.0}) {
          TraceOnce(whitted, camera.Eye(), camera.DirectionThrough(x + u, y + v), rng, tree, stats);
          for (std::size_t k = 0; k < tree.Size(); ++k) {
            coversO2 |= lit.ObjectName(tree[static_cast<std::uint32_t>(k)].object) == "O2";
          }
        }
      }
      if (!coversO2) {
        ++untouched;
        ASSERT_LT(MaxComponent(glm::abs(c.At(x, y) - b.At(x, y))), 1e-9) << x << "," << y;
      }
    }
  }
  EXPECT_GT(untouched, 3000);  // most of the 4096 pixels never meet O2
}

// The colour of tree node i with the children of every hit on `object` weighted by the
// cosine at that hit: C' = L_local + sum_j W_j cos(theta) C'_j, where L_local = C - sum_j
// W_j C_j. For a mirror reflection r = d - 2 (d.n) n, so cos(theta) = |r - d| / 2.
Colour CosineWeightedAt(const RayTree& tree, std::uint32_t i, std::int32_t object) {
  const Ray& ray = tree[i];
  Colour colour = ray.colour;
  for (std::uint32_t c = 0; c < ray.childCount; ++c) {
    const Ray& child = tree[ray.firstChild + c];
    const double w =
        ray.object == object ? 0.5 * glm::length(child.direction - ray.direction) : 1.0;
    colour +=
        child.weight * (w * CosineWeightedAt(tree, ray.firstChild + c, object) - child.colour);
  }
  return colour;
}

// A Phong object with a huge exponent is the mirror weighted by cos(theta) at each hit
// (spec, "Objects"): its lobe's albedo tends to rho cos(theta), the mirror's is rho.
TEST(Stability, HugePhongExponentEqualsTheMirrorWeightedByTheCosine) {
  constexpr int kSize = 32;
  constexpr int kBlock = 8;
  // Many short runs: the standard error of each block comes from the spread of the runs,
  // and with few runs its t-distribution's tails would fail blocks by chance.
  constexpr int kSpp = 16;
  const Scene phong = CanonicalScene({"/objects/0/exponent=1e5"});
  const Scene mirror = CanonicalScene({"/objects/0/material=mirror"});
  const std::int32_t o1 = phong.spheres[0].Object();
  ASSERT_EQ(mirror.ObjectName(o1), "O1");
  const std::vector<MeanAndError> a =
      testing::RenderBlocks(phong, {}, kSize, kBlock, kSpp, 64, 10, Image(kSize, kSize),
                            SamplerKind::Random)
          .blocks;
  // The mirror scene, traced sample by sample so that each tree can be re-weighted.
  const MonteCarloIntegrator integrator(mirror, {});
  const Camera camera(mirror.wall, mirror.camera, kSize, kSize);
  constexpr int kBlocks = kSize / kBlock;
  std::vector<MeanAndError> plain(kBlocks * kBlocks * 3);
  std::vector<MeanAndError> weighted(kBlocks * kBlocks * 3);
  RayTree tree;
  RenderStats stats;
  for (int run = 0; run < 128; ++run) {
    std::vector<Colour> sumPlain(kBlocks * kBlocks, Colour(0.0));
    std::vector<Colour> sumWeighted(kBlocks * kBlocks, Colour(0.0));
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        Pcg32 rng(static_cast<std::uint64_t>(100 + run), static_cast<std::uint64_t>(y * kSize + x));
        const std::size_t blockIndex =
            static_cast<std::size_t>((y / kBlock) * kBlocks + x / kBlock);
        for (int s = 0; s < kSpp; ++s) {
          const double u = rng.Uniform();
          const double v = rng.Uniform();
          const Colour c = TraceOnce(integrator, camera.Eye(),
                                     camera.DirectionThrough(x + u, y + v), rng, tree, stats);
          sumPlain[blockIndex] += c / double{kSpp};
          sumWeighted[blockIndex] += CosineWeightedAt(tree, 0, o1) / double{kSpp};
        }
      }
    }
    for (std::size_t i = 0; i < sumPlain.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        plain[i * 3 + static_cast<std::size_t>(k)].Add(sumPlain[i][k] / (kBlock * kBlock));
        weighted[i * 3 + static_cast<std::size_t>(k)].Add(sumWeighted[i][k] / (kBlock * kBlock));
      }
    }
  }
  int differsFromPlain = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double se = std::hypot(a[i].StandardError(), weighted[i].StandardError());
    EXPECT_LE(std::abs(a[i].mean - weighted[i].mean), 4.0 * se)
        << "block " << i / 3 << " channel " << i % 3 << ": " << a[i].mean << " vs "
        << weighted[i].mean << " z " << (a[i].mean - weighted[i].mean) / se;
    const double sePlain = std::hypot(a[i].StandardError(), plain[i].StandardError());
    differsFromPlain += std::abs(a[i].mean - plain[i].mean) > 4.0 * sePlain ? 1 : 0;
  }
  // ... and is not the mirror itself: where O1 is seen at an angle, the two differ.
  EXPECT_GE(differsFromPlain, 3);
}

TEST(Stability, PhongExponentsZeroAndOneAreFiniteAndConserveEnergy) {
  Pcg32 rng(8, 8);
  for (double exponent : {0.0, 1.0}) {
    Material m;
    m.type = MaterialType::Phong;
    m.reflectance = Colour(0.9);
    m.exponent = exponent;
    for (double degrees : {0.0, 30.0, 60.0, 89.0}) {
      const double th = degrees * kPi / 180.0;
      const vec3 d(std::sin(th), 0.0, -std::cos(th));
      MeanAndError albedo;
      for (int i = 0; i < 100000; ++i) {
        const PhongSample s = SamplePhong(m, d, vec3(0, 0, 1), rng.Uniform(), rng.Uniform());
        ASSERT_TRUE(IsFinite(s.weight) && std::isfinite(s.pdf));
        albedo.Add(s.weight.x);
      }
      EXPECT_LE(albedo.mean, 0.9 + 3.0 * albedo.StandardError()) << exponent << " " << degrees;
    }
    const Scene scene = CanonicalScene({"/objects/0/exponent=" + std::to_string(exponent),
                                        "/objects/2/exponent=" + std::to_string(exponent)});
    RenderStats stats;
    RenderImage(scene, MonteCarloIntegrator(scene, {}), 48, 4, 1, &stats);
    EXPECT_EQ(stats.nonFiniteSamples, 0u);
  }
}

// Rays from inside a glass object: every hit is that object from inside (no escape
// through a wrong face), children weigh no more than their parent, and past the critical
// angle the one child stays inside.
// A ray inside `name` may end on the glass or, for an object resting on the floor, on the
// floor exactly under it (the contact face: a tie the floor wins, so nothing escapes).
bool HitFromInsideIsRight(const Scene& scene, const std::string& name, const Ray& node) {
  if (scene.ObjectName(node.object) == name) return true;
  return scene.ObjectName(node.object) == "W4" && std::abs(node.end.y) < 1e-12 &&
         node.end.x >= 0.42 && node.end.x <= 0.70 && node.end.z >= 0.06 && node.end.z <= 0.34;
}

void CheckRaysInside(const Scene& scene, const std::string& name, vec3 centre, double extent,
                     int minimumTotalInternal) {
  const WhittedIntegrator integrator(scene, 10);
  Pcg32 rng(4, 4);
  RayTree tree;
  RenderStats stats;
  int totalInternal = 0;
  for (int i = 0; i < 20000; ++i) {
    const double z = 2.0 * rng.Uniform() - 1.0;
    const double phi = 2.0 * kPi * rng.Uniform();
    const vec3 d(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    const vec3 start =
        centre + extent * vec3(rng.Uniform() - 0.5, rng.Uniform() - 0.5, rng.Uniform() - 0.5);
    Hit hit;
    ASSERT_TRUE(scene.Intersect(start, d, hit, false));
    Ray probe;
    probe.object = hit.object;
    probe.end = hit.point;
    ASSERT_TRUE(HitFromInsideIsRight(scene, name, probe)) << "escaped through a wrong face";
    if (scene.ObjectName(hit.object) != name) continue;  // the contact face
    ASSERT_GT(glm::dot(d, hit.normal), 0.0);
    const double f = FresnelDielectric(d, hit.normal, 1.5);
    const double cosI = glm::dot(d, hit.normal);
    const bool past = 1.5 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI)) >= 1.0;
    if (past) {
      ++totalInternal;
      ASSERT_EQ(f, 1.0);
      ASSERT_FALSE(Refract(d, hit.normal, 1.5).has_value());
    }
    tree.Clear();
    Ray ray;
    ray.start = start;
    ray.direction = d;
    ray.inside = true;
    Sampler sampler(rng);
    const Colour c = integrator.Trace(tree, tree.Add(ray), PixelShaft{}, sampler, stats);
    rng = sampler.Generator();
    ASSERT_TRUE(IsFinite(c));
    const Ray& root = tree[0];
    double weights = 0.0;
    for (std::uint32_t k = 0; k < root.childCount; ++k)
      weights += tree[root.firstChild + k].weight.x;
    ASSERT_LE(weights, 1.0 + 1e-12);
    if (past) {
      ASSERT_EQ(root.childCount, 1u);
      const Ray& child = tree[root.firstChild];
      ASSERT_TRUE(child.inside);
      ASSERT_TRUE(HitFromInsideIsRight(scene, name, child)) << "a totally reflected ray got out";
    }
    // Everywhere in the tree: a ray marked inside ends on glass (or the contact face).
    for (std::size_t k = 0; k < tree.Size(); ++k) {
      const Ray& node = tree[static_cast<std::uint32_t>(k)];
      if (node.inside) {  // inside some glass object: O2, or O3 where it is glass too
        const bool glass =
            HitFromInsideIsRight(scene, name, node) || HitFromInsideIsRight(scene, "O2", node);
        ASSERT_TRUE(glass) << "node " << k << " (depth " << int(node.depth) << ", kind "
                           << int(node.kind) << ") hit " << scene.ObjectName(node.object) << " at ("
                           << node.end.x << ", " << node.end.y << ", " << node.end.z << ") from ("
                           << node.start.x << ", " << node.start.y << ", " << node.start.z << ")";
      }
    }
  }
  EXPECT_GT(totalInternal, minimumTotalInternal);
}

TEST(Stability, RaysInsideGlassSphereAndCube) {
  CheckRaysInside(CanonicalScene(), "O2", vec3(0.74, 0.16, 0.70), 0.15, 100);
  const Scene glassCube = CanonicalScene(
      {"/objects/2/material=glass", "/objects/2/ior=1.5", "/objects/2/reflectance=null"});
  CheckRaysInside(glassCube, "O3", vec3(0.56, 0.14, 0.20), 0.27, 1000);
}

TEST(Stability, EdgesCornersTangentsAndGrazingRaysNeitherLeakNorMakeNaN) {
  const Scene scene = CanonicalScene();
  const WhittedIntegrator whitted(scene, 10);
  MonteCarloOptions o;
  o.walls = MonteCarloOptions::Walls::Diffuse;
  const MonteCarloIntegrator mc(scene, o);
  const vec3 eye = scene.camera.eye;
  std::vector<std::pair<vec3, vec3>> rays;  // start, direction: all must hit something
  // Along the cube's top edges and through its corners, from inside the room.
  rays.push_back({vec3(0.42, 0.28, 0.9), vec3(0, 0, -1)});
  rays.push_back({vec3(0.70, 0.28, 0.9), vec3(0, 0, -1)});
  rays.push_back({vec3(0.1, 0.28, 0.34), vec3(1, 0, 0)});
  rays.push_back({vec3(0.5, 0.8, 0.9), vec3(0.42, 0.28, 0.34) - vec3(0.5, 0.8, 0.9)});
  rays.push_back({vec3(0.9, 0.6, 0.6), vec3(0.70, 0.28, 0.34) - vec3(0.9, 0.6, 0.6)});
  // Into the room's own corners and along its edges.
  for (double x : {0.0, 1.0}) {
    for (double y : {0.0, 1.0}) {
      rays.push_back({vec3(0.5, 0.5, 0.5), vec3(x, y, 0.0) - vec3(0.5, 0.5, 0.5)});
      rays.push_back({vec3(x, y, 0.9), vec3(0, 0, -1)});
    }
  }
  // Tangent to O1 from the eye, and grazing the floor and the back wall.
  const vec3 c(0.22, 0.18, 0.40);
  const vec3 toC = c - eye;
  const vec3 side = glm::normalize(glm::cross(toC, vec3(0, 1, 0)));
  const double dist = glm::length(toC);
  const double alpha = std::asin(0.18 / dist);
  rays.push_back({eye, glm::normalize(toC) * std::cos(alpha) + side * std::sin(alpha)});
  rays.push_back({vec3(0.5, 1e-12, 0.9), vec3(0.1, 0.0, -1.0)});
  rays.push_back({vec3(0.5, 0.3, 1e-12), vec3(1.0, 0.2, 0.0)});
  Pcg32 rng(6, 6);
  RayTree tree;
  RenderStats stats;
  for (const auto& [start, d] : rays) {
    Hit hit;
    ASSERT_TRUE(scene.Intersect(start, glm::normalize(d), hit, true))
        << "leaked out of the room from (" << start.x << ", " << start.y << ", " << start.z << ")";
    ASSERT_TRUE(IsFinite(hit.point));
    for (int k = 0; k < 100; ++k) {
      ASSERT_TRUE(IsFinite(TraceOnce(whitted, start, d, rng, tree, stats)));
      ASSERT_TRUE(IsFinite(TraceOnce(mc, start, d, rng, tree, stats)));
    }
  }
  EXPECT_EQ(stats.nonFiniteSamples, 0u);
}

TEST(Stability, NoLightLeaksAtContactLinesOrAroundTheCoplanarLight) {
  const Scene scene = CanonicalScene();
  const MonteCarloIntegrator mc(scene, {});
  Pcg32 rng(2, 2);
  RayTree tree;
  RenderStats stats;
  // Floor points next to O1's contact point (0.22, 0, 0.40) see only the sphere above.
  for (double r : {1e-6, 1e-4, 1e-3, 0.01, 0.02}) {
    for (int k = 0; k < 8; ++k) {
      const double phi = 2.0 * kPi * k / 8.0;
      const vec3 p(0.22 + r * std::cos(phi), 0.0, 0.40 + r * std::sin(phi));
      const vec3 from = p + vec3(0.0, 1e-3, 0.2);  // under the sphere, looking at p
      for (int i = 0; i < 200; ++i) {
        ASSERT_EQ(TraceOnce(mc, from, p - from, rng, tree, stats), Colour(0.0))
            << "light under O1 at distance " << r;
      }
    }
  }
  // The ceiling a hair outside the light is black (terminal walls); a hair inside is Le.
  const Rectangle& l = scene.light->Shape();
  const vec3 below(0.5, 0.5, 0.5);
  for (double e : {1e-9, 1e-6}) {
    for (const vec3 p :
         {l.PointFromUV(0.5, 0.0) - vec3(0, 0, e), l.PointFromUV(1.0, 0.5) + vec3(e, 0, 0)}) {
      EXPECT_EQ(TraceOnce(mc, below, p - below, rng, tree, stats), Colour(0.0));
    }
    for (const vec3 p :
         {l.PointFromUV(0.5, 0.0) + vec3(0, 0, e), l.PointFromUV(1.0, 0.5) - vec3(e, 0, 0)}) {
      EXPECT_EQ(TraceOnce(mc, below, p - below, rng, tree, stats), Colour(50.0));
    }
  }
}

TEST(Stability, NoShadowAcneOnAnUnoccludedPatch) {
  // Whitted: every point of a back-wall patch equals the closed form exactly.
  const Scene scene = CanonicalScene();
  const WhittedIntegrator whitted(scene, 10);
  Pcg32 rng(1, 2);
  RayTree tree;
  RenderStats stats;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      const vec3 p(0.2 + 0.6 * i / 39.0, 0.45 + 0.5 * j / 39.0, 0.0);
      Colour expected(0.0);
      for (const PointLight& light : scene.pointLights) {
        const vec3 l = light.position - p;
        expected +=
            Colour(0.75) * kInvPi * light.intensity * (l.z / glm::length(l)) / glm::dot(l, l);
      }
      const vec3 from = p + vec3(0.0, 0.0, 0.3);
      const Colour c = TraceOnce(whitted, from, p - from, rng, tree, stats);
      ASSERT_NEAR(c.y, expected.y, 1e-12 * expected.y) << p.x << " " << p.y;
    }
  }
  // Monte Carlo: 400 floor points under the light, each within the noise of Lambert's
  // value: |z| < 4.5 (a Sidak bound for 400 points at level 0.01 is 4.05).
  const MonteCarloIntegrator mc(scene, {});
  const Rectangle& l = scene.light->Shape();
  const std::vector<vec3> corners = {l.PointFromUV(0, 0), l.PointFromUV(1, 0), l.PointFromUV(1, 1),
                                     l.PointFromUV(0, 1)};
  double worst = 0.0;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      const vec3 p(0.30 + 0.15 * i / 19.0, 0.0, 0.62 + 0.28 * j / 19.0);
      const double expected =
          0.75 * kInvPi * 50.0 * testing::PolygonCosineIntegral(p, vec3(0, 1, 0), corners);
      MeanAndError m;
      const vec3 from = p + vec3(0.0, 0.05, 0.05);
      for (int n = 0; n < 2000; ++n) m.Add(TraceOnce(mc, from, p - from, rng, tree, stats).x);
      worst = std::max(worst, std::abs(m.mean - expected) / m.StandardError());
    }
  }
  EXPECT_LT(worst, 4.5);
}

TEST(Stability, NoNaNOrInfInAnyModeOrSwitchAt128) {
  const Scene scene = CanonicalScene();
  using O = MonteCarloOptions;
  RenderStats stats;
  RenderImage(scene, WhittedIntegrator(scene, 10), 128, 1, 1, &stats);
  EXPECT_EQ(stats.nonFiniteSamples, 0u) << "whitted";
  for (O::Walls walls : {O::Walls::Terminal, O::Walls::Diffuse}) {
    for (O::Strategy strategy : {O::Strategy::Mis, O::Strategy::Light, O::Strategy::Brdf}) {
      for (O::Glass glass : {O::Glass::Split, O::Glass::Choose}) {
        for (O::Fresnel fresnel : {O::Fresnel::Exact, O::Fresnel::SmallAngle}) {
          for (int branches : {1, 3}) {
            O o;
            o.walls = walls;
            o.strategy = strategy;
            o.glass = glass;
            o.fresnel = fresnel;
            o.branches = branches;
            RenderImage(scene, MonteCarloIntegrator(scene, o), 128, 1, 1, &stats);
            ASSERT_EQ(stats.nonFiniteSamples, 0u);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace glint
