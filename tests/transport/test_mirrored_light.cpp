// Next-event estimation of the light seen in mirrors: Lambert's closed form for a plane
// mirror's image of the light, agreement with rays aimed at the mirrors that find the
// light in them, and images with and without it that agree block by block, each test
// with the power to see a 1% bias.
#include <gtest/gtest.h>

#include <cstdio>

#include "glint/camera/Camera.hpp"
#include "glint/image/BiasTest.hpp"
#include "glint/sampling/Sampling.hpp"
#include "glint/transport/MirroredLight.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Power.hpp"
#include "support/Statistics.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::ExpectAgreementWithPower;
using testing::MeanAndError;
using testing::PolygonCosineIntegral;
using testing::RenderWithSampler;
using testing::SourcePath;

Scene MirrorScene(const std::vector<std::string>& overrides = {}) {
  return LoadScene(SourcePath("scenes/cornell-mirror.json"), overrides);
}

// Irradiance at x from the light seen in the mirrors, by MirroredLight, every channel.
struct ColourEstimate {
  MeanAndError c[3];
  void Add(Colour v) {
    for (int k = 0; k < 3; ++k) c[k].Add(v[k]);
  }
};

ColourEstimate MirroredLightColour(const Scene& scene, vec3 x, vec3 n, int count,
                                   std::uint64_t seed) {
  const MirroredLight mirrored(scene, *scene.light);
  Pcg32 rng(seed, 1);
  RenderStats stats;
  ColourEstimate m;
  for (int i = 0; i < count; ++i) {
    const double u = rng.Uniform();
    m.Add(mirrored.Irradiance(x, n, u, rng.Uniform(), stats));
  }
  return m;
}

// One channel of it.
MeanAndError EstimateByMirroredLight(const Scene& scene, vec3 x, vec3 n, int count, int channel,
                                     std::uint64_t seed) {
  return MirroredLightColour(scene, x, n, count, seed).c[channel];
}

// The same irradiance E = int rho Le cos dw over the directions that meet a mirror and,
// reflected, the light, from rays aimed where such directions are: uniform in a cone,
// one of M cones chosen with probability 1/M (one-sample MIS with the balance
// heuristic, Veach 1997 eq. 9.15):
//   pdf(w) = sum_j [w in cone j] / (M Omega_j),  Omega_j = 2 pi (1 - cos theta_j).
// The cones: each mirror sphere's bounding sphere (chosen with probability 0.1, so that
// every direction to it keeps a density: a defensive mixture) and a tight cone around the
// directions a scan of the sphere found to reach the light; and for each face of a
// mirror cube that x is in front of, the bounding sphere of the light reflected in the
// face's plane (a ray that the face reflects to the light heads, unfolded, for that
// image). A ray brings rho Le cos / pdf when it does meet a mirror and then the light;
// it shares nothing with MirroredLight but the scene's intersection code.
struct Cone {
  vec3 axis;
  double cosMax;
  double solidAngle;
  double probability = 1.0;  // of choosing it (relative; normalised below)

  static Cone Around(vec3 x, vec3 centre, double radius) {
    const vec3 d = centre - x;
    const double dist = glm::length(d);
    EXPECT_GT(dist, radius) << "the point lies inside a bounding sphere";
    const double cosMax = std::sqrt(1.0 - radius * radius / (dist * dist));
    return {d / dist, cosMax, 2.0 * kPi * (1.0 - cosMax)};
  }
  vec3 Sample(Pcg32& rng) const {
    const double cosTheta = 1.0 - rng.Uniform() * (1.0 - cosMax);
    const double phi = 2.0 * kPi * rng.Uniform();
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return Frame::FromZ(axis).ToWorld(
        vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
  }
  double Pdf(vec3 w) const { return glm::dot(w, axis) >= cosMax ? 1.0 / solidAngle : 0.0; }
};

// What a ray from x along w brings: rho Le if it meets a mirror first and, reflected,
// the light; and the reflected ray, for the caller.
Colour MirrorThenLight(const Scene& scene, vec3 x, vec3 n, vec3 w) {
  Hit hit;
  if (!scene.Intersect(OffsetRayOrigin(x, n, w), w, hit, true) || hit.light ||
      hit.material->type != MaterialType::Mirror) {
    return Colour(0.0);
  }
  const vec3 r = Reflect(w, hit.normal);
  Hit second;
  if (!scene.Intersect(OffsetRayOrigin(hit.point, hit.normal, r), r, second, true) ||
      !second.light) {
    return Colour(0.0);
  }
  return hit.material->reflectance * scene.light->Le(-r);
}

ColourEstimate RaysAtTheMirrors(const Scene& scene, vec3 x, vec3 n, int count, std::uint64_t seed) {
  std::vector<Cone> cones;
  Pcg32 rng(seed, 3);
  for (const Sphere& s : scene.spheres) {
    if (s.GetMaterial().type != MaterialType::Mirror) continue;
    // The whole sphere, chosen rarely (so that every direction to it has a density), and
    // a tight cone around the directions a scan of it found to reach the light.
    Cone whole = Cone::Around(x, s.Centre(), s.Radius());
    vec3 sum(0.0);
    std::vector<vec3> found;
    for (int i = 0; i < 100000; ++i) {
      const vec3 w = whole.Sample(rng);
      if (glm::dot(n, w) > 0.0 && MirrorThenLight(scene, x, n, w) != Colour(0.0)) {
        found.push_back(w);
        sum += w;
      }
    }
    whole.probability = found.empty() ? 1.0 : 0.1;
    cones.push_back(whole);
    if (found.empty()) continue;
    const vec3 axis = glm::normalize(sum);
    double cosMin = 1.0;
    for (const vec3 w : found) cosMin = std::min(cosMin, glm::dot(w, axis));
    const double angle = std::min(kPi / 2.0, 1.5 * std::acos(cosMin) + 1e-3);
    cones.push_back({axis, std::cos(angle), 2.0 * kPi * (1.0 - std::cos(angle)), 0.9});
  }
  const Rectangle& light = scene.light->Shape();
  const vec3 corners[4] = {light.PointFromUV(0, 0), light.PointFromUV(1, 0),
                           light.PointFromUV(1, 1), light.PointFromUV(0, 1)};
  for (const Cube& c : scene.cubes) {
    if (c.GetMaterial().type != MaterialType::Mirror) continue;
    for (int axis = 0; axis < 3; ++axis) {
      for (const double side : {-1.0, 1.0}) {
        const double plane = c.Centre()[axis] + side * 0.5 * c.Size();
        if ((x[axis] - plane) * side <= 0.0) continue;  // x is behind this face
        vec3 image[4];
        vec3 centre(0.0);
        for (int i = 0; i < 4; ++i) {
          image[i] = corners[i];
          image[i][axis] = 2.0 * plane - corners[i][axis];
          centre += 0.25 * image[i];
        }
        double radius = 0.0;
        for (const vec3 p : image) radius = std::max(radius, glm::length(p - centre));
        cones.push_back(Cone::Around(x, centre, radius * (1.0 + 1e-9)));
      }
    }
  }
  double total = 0.0;
  for (const Cone& c : cones) total += c.probability;
  for (Cone& c : cones) c.probability /= total;
  ColourEstimate m;
  for (int i = 0; i < count; ++i) {
    double u = rng.Uniform();
    std::size_t j = 0;
    while (j + 1 < cones.size() && u >= cones[j].probability) u -= cones[j++].probability;
    const vec3 w = cones[j].Sample(rng);
    const double cosine = glm::dot(n, w);
    Colour e(0.0);
    if (cosine > 0.0) {
      const Colour f = MirrorThenLight(scene, x, n, w);
      if (f != Colour(0.0)) {
        double pdf = 0.0;
        for (const Cone& c : cones) pdf += c.probability * c.Pdf(w);
        e = f * (cosine / pdf);
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
    testing::ExpectNearWithPower(m.mean, m.StandardError(), expected,
                                 "channel " + std::to_string(channel));
    std::printf("channel %d: mirrored light %.6f +- %.6f, Lambert %.6f (%+.2f standard errors)\n",
                channel, m.mean, m.StandardError(), expected,
                (m.mean - expected) / m.StandardError());
  }
}

TEST(MirroredLight, AgreesWithRaysThatFindTheLightInAMirror) {
  // The mirror scene as it is: the mirror sphere O1 and cube O3 (with the glass sphere
  // and each other in the way), at points that see the light in one or both.
  const Scene scene = MirrorScene();
  struct Case {
    const char* name;
    vec3 x, n;
    int rays;
  };
  const Case cases[] = {
      {"back wall, the cube's top and the sphere", vec3(0.56, 0.6, 0.0), vec3(0, 0, 1), 2000000},
      {"left wall beside the sphere", vec3(0.0, 0.3, 0.42), vec3(1, 0, 0), 8000000},
      {"ceiling over the cube", vec3(0.56, 1.0, 0.1), vec3(0, -1, 0), 2000000},
      {"floor before the cube", vec3(0.55, 0.0, 0.37), vec3(0, 1, 0), 2000000},
  };
  std::uint64_t seed = 10;
  for (const Case& c : cases) {
    const ColourEstimate nee = MirroredLightColour(scene, c.x, c.n, 400000, seed++);
    const ColourEstimate rays = RaysAtTheMirrors(scene, c.x, c.n, c.rays, seed++);
    for (int k = 0; k < 3; ++k) {
      const MeanAndError& a = nee.c[k];
      const MeanAndError& b = rays.c[k];
      const double se = std::hypot(a.StandardError(), b.StandardError());
      std::printf(
          "%s, channel %d: mirrored light %.6f +- %.6f, rays at the mirrors %.6f +- %.6f "
          "(%+.2f sigma); a 1%% bias is %.1f sigma\n",
          c.name, k, a.mean, a.StandardError(), b.mean, b.StandardError(), (a.mean - b.mean) / se,
          0.01 * a.mean / se);
      // Power: a 1% difference is at least 5 standard errors, so 1.01 times either side
      // fails the 4-sigma test below unless chance hides it by more than one sigma.
      ASSERT_LT(5.0 * se, 0.01 * a.mean) << c.name << ", channel " << k;
      EXPECT_LE(std::abs(a.mean - b.mean), 4.0 * se) << c.name << ", channel " << k;
      EXPECT_GT(std::abs(1.01 * a.mean - b.mean), 4.0 * se) << c.name << ", channel " << k;
      EXPECT_GT(std::abs(a.mean - 1.01 * b.mean), 4.0 * se) << c.name << ", channel " << k;
    }
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
  // glint render's path: shafts and the default sampler (sobol); the pilot weighs pixels.
  const SamplerKind sobol = SamplerKind::Sobol;
  const Image pilot = RenderWithSampler(scene, withoutNee, SamplerKind::Random, 64, 16, 99);
  const Image a = RenderWithSampler(scene, withNee, sobol, 64, 512, 21);
  const Image b = RenderWithSampler(scene, withNee, sobol, 64, 512, 22);
  const Image r1 = RenderWithSampler(scene, withoutNee, sobol, 64, 512, 11);
  const Image r2 = RenderWithSampler(scene, withoutNee, sobol, 64, 512, 12);
  ExpectAgreementWithPower("mirrored light against brdf rays", a, b, r1, &r2, pilot);
  const std::vector<const Image*> all = {&a, &b, &r1, &r2};
  const double ratio = RelativeNoise(r1, r2, all) / RelativeNoise(a, b, all);
  std::printf("noise variance %.2fx lower with the mirrored light\n", ratio);
  EXPECT_GT(ratio, 2.0);
}

}  // namespace
}  // namespace glint
