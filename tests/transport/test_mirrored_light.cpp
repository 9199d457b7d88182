// Next-event estimation of the light seen in mirrors: Lambert's closed form for a plane
// mirror's image of the light, agreement with cosine-sampled rays that find the light in
// a mirror, and images with and without it that agree block by block.
#include <gtest/gtest.h>

#include <cstdio>

#include "glint/camera/Camera.hpp"
#include "glint/image/BiasTest.hpp"
#include "glint/sampling/Sampling.hpp"
#include "glint/transport/MirroredLight.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::MeanAndError;
using testing::PolygonCosineIntegral;
using testing::RenderWithSampler;
using testing::SourcePath;

Scene MirrorScene(const std::vector<std::string>& overrides = {}) {
  return LoadScene(SourcePath("scenes/cornell-mirror.json"), overrides);
}

MeanAndError EstimateByMirroredLight(const Scene& scene, vec3 x, vec3 n, int count, int channel,
                                     std::uint64_t seed) {
  const MirroredLight mirrored(scene, *scene.light);
  Pcg32 rng(seed, 1);
  RenderStats stats;
  MeanAndError m;
  for (int i = 0; i < count; ++i) {
    const double u = rng.Uniform();
    m.Add(mirrored.Irradiance(x, n, u, rng.Uniform(), stats)[channel]);
  }
  return m;
}

// The same irradiance from cosine-distributed rays: those that hit a mirror first and,
// reflected, the light, bring rho Le; E = pi E[L] for p(w) = cos / pi.
MeanAndError EstimateByCosineRays(const Scene& scene, vec3 x, vec3 n, int count, int channel,
                                  std::uint64_t seed) {
  const Frame frame = Frame::FromZ(n);
  Pcg32 rng(seed, 2);
  MeanAndError m;
  for (int i = 0; i < count; ++i) {
    const double u = rng.Uniform();
    const vec3 w = frame.ToWorld(SampleCosineHemisphere(u, rng.Uniform()));
    Hit hit;
    double e = 0.0;
    if (scene.Intersect(OffsetRayOrigin(x, n, w), w, hit, true) && !hit.light &&
        hit.material->type == MaterialType::Mirror) {
      const vec3 r = Reflect(w, hit.normal);
      Hit second;
      if (scene.Intersect(OffsetRayOrigin(hit.point, hit.normal, r), r, second, true) &&
          second.light) {
        e = kPi * hit.material->reflectance[channel] * scene.light->Le(-r)[channel];
      }
    }
    m.Add(e);
  }
  return m;
}

TEST(MirroredLight, APlaneMirrorShowsTheLightsImageByLambertsFormula) {
  // The mirror cube alone; a point on the back wall sees the whole light's image in the
  // cube's top face (y = 0.28): the light reflected in that plane, as if it were there.
  const Scene scene = MirrorScene(
      {R"(/objects=[{"id": "O3", "type": "cube", "position": [0.42, 0.0, 0.06], "size": 0.28,
                     "material": "mirror", "reflectance": [0.85, 0.75, 0.45]}])"});
  const vec3 x(0.56, 0.6, 0.0);
  const vec3 n(0.0, 0.0, 1.0);
  const Rectangle& light = scene.light->Shape();
  std::vector<vec3> image;
  for (const vec3 c : {light.PointFromUV(0, 0), light.PointFromUV(1, 0), light.PointFromUV(1, 1),
                       light.PointFromUV(0, 1)}) {
    image.emplace_back(c.x, 2.0 * 0.28 - c.y, c.z);
    // The whole image is seen through the face: each corner's line of sight crosses it.
    const vec3 crossing = x + (x.y - 0.28) / (x.y - image.back().y) * (image.back() - x);
    ASSERT_TRUE(crossing.x > 0.42 && crossing.x < 0.70 && crossing.z > 0.06 && crossing.z < 0.34);
  }
  for (int channel = 0; channel < 3; ++channel) {
    const double rho = scene.cubes[0].GetMaterial().reflectance[channel];
    const double expected = rho * 50.0 * PolygonCosineIntegral(x, n, image);
    const MeanAndError m = EstimateByMirroredLight(scene, x, n, 100000, channel, 1 + channel);
    ASSERT_LT(3.0 * m.StandardError(), 0.003 * expected);
    EXPECT_NEAR(m.mean, expected, 3.0 * m.StandardError());
    std::printf("channel %d: mirrored light %.6f +- %.6f, Lambert %.6f (%+.2f standard errors)\n",
                channel, m.mean, m.StandardError(), expected,
                (m.mean - expected) / m.StandardError());
  }
}

TEST(MirroredLight, AgreesWithCosineRaysThatFindTheLightInAMirror) {
  // The mirror scene as it is: the mirror sphere O1 and cube O3 (with the glass sphere
  // and each other in the way), at points that see the light in one or both.
  const Scene scene = MirrorScene();
  struct Case {
    const char* name;
    vec3 x, n;
    int rays;
  };
  const Case cases[] = {
      {"back wall, the cube's top and the sphere", vec3(0.56, 0.6, 0.0), vec3(0, 0, 1), 4000000},
      {"left wall beside the sphere", vec3(0.0, 0.3, 0.42), vec3(1, 0, 0), 4000000},
      {"ceiling over the cube", vec3(0.56, 1.0, 0.1), vec3(0, -1, 0), 2000000},
      {"floor before the cube", vec3(0.55, 0.0, 0.37), vec3(0, 1, 0), 2000000},
  };
  std::uint64_t seed = 10;
  for (const Case& c : cases) {
    const MeanAndError nee = EstimateByMirroredLight(scene, c.x, c.n, 200000, 0, seed++);
    const MeanAndError rays = EstimateByCosineRays(scene, c.x, c.n, c.rays, 0, seed++);
    const double se = std::hypot(nee.StandardError(), rays.StandardError());
    std::printf("%s: mirrored light %.6f +- %.6f, cosine rays %.6f +- %.6f (%+.2f sigma)\n", c.name,
                nee.mean, nee.StandardError(), rays.mean, rays.StandardError(),
                (nee.mean - rays.mean) / se);
    // Each comparison can see a 5% difference (four standard errors are below 5%).
    ASSERT_LT(4.0 * se, 0.05 * nee.mean) << c.name;
    EXPECT_NEAR(nee.mean, rays.mean, 4.0 * se) << c.name;
  }
}

// The relative variance of one image's pixels, from two independent renders a and b:
// the mean of (a - b)^2 / 2 / (r^2 + 0.01), r the mean of the images given, as relative
// MSE weighs errors (the light's own pixels would swamp a plain variance).
double RelativeNoise(const Image& a, const Image& b, const std::vector<const Image*>& all) {
  double sum = 0.0;
  for (int y = 0; y < a.Height(); ++y) {
    for (int x = 0; x < a.Width(); ++x) {
      Colour r(0.0);
      for (const Image* i : all) r += i->At(x, y) / static_cast<double>(all.size());
      const Colour d = a.At(x, y) - b.At(x, y);
      for (int k = 0; k < 3; ++k) sum += 0.5 * d[k] * d[k] / (r[k] * r[k] + 0.01);
    }
  }
  return sum / (3.0 * a.Width() * a.Height());
}

// The whole integrator: the light a wall sees in a mirror is counted once, by next-event
// estimation, and the mirror ray of a diffuse ray that finds the light counts nothing;
// a camera ray's reflection still shows the light. Same image as without it, less noise.
TEST(MirroredLight, ImagesWithAndWithoutItAgreeBlockByBlockAndItsNoiseIsLower) {
  const Scene scene = MirrorScene();
  MonteCarloOptions nee;
  nee.walls = MonteCarloOptions::Walls::Diffuse;
  MonteCarloOptions brdf = nee;
  brdf.mirrorLight = MonteCarloOptions::MirrorLight::Brdf;
  const MonteCarloIntegrator withNee(scene, nee);
  const MonteCarloIntegrator withoutNee(scene, brdf);
  const Image a = RenderWithSampler(scene, withNee, SamplerKind::Random, 64, 64, 21);
  const Image b = RenderWithSampler(scene, withNee, SamplerKind::Random, 64, 64, 22);
  const Image r1 = RenderWithSampler(scene, withoutNee, SamplerKind::Random, 64, 64, 11);
  const Image r2 = RenderWithSampler(scene, withoutNee, SamplerKind::Random, 64, 64, 12);
  const BiasVerdict v = TestBias(a, b, r1, &r2);
  const std::vector<const Image*> all = {&a, &b, &r1, &r2};
  const double ratio = RelativeNoise(r1, r2, all) / RelativeNoise(a, b, all);
  std::printf(
      "with against without: mean ratio %.5f (z %+.2f), max block z %.2f; noise variance "
      "%.2fx lower\n",
      v.meanRatio, v.meanZ, v.maxBlockZ, ratio);
  EXPECT_TRUE(v.agree) << "mean z " << v.meanZ << ", " << v.failedBlocks << " blocks beyond "
                       << v.blockLimit;
  EXPECT_GT(ratio, 2.0);
}

}  // namespace
}  // namespace glint
