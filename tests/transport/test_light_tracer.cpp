// Light tracing (LightTracer): the camera's importance W_e against a closed form (light
// tracing alone estimates a diffuse scene's directly lit surfaces as the camera's
// next-event estimation does), and the caustic paths counted once (images with
// --caustics light and off agree block by block, with the power to see a 1% bias, for
// mirrors and glass and for Phong objects under each --strategy).
#include <gtest/gtest.h>

#include <cstdio>

#include "glint/camera/Camera.hpp"
#include "glint/transport/LightTracer.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/MonteCarloTesting.hpp"
#include "support/Power.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::ExpectAgreementWithPower;
using testing::RenderWithSampler;
using testing::SourcePath;

constexpr int kSize = 64;

// The camera's rays see only the light itself; everything else in the image is light
// tracing's: the light's paths joined to the eye where they first land (Joins::Direct).
class LightAlone final : public Integrator {
 public:
  LightAlone(const Scene& scene, const Pinhole& camera)
      : scene_(scene),
        tracer_(scene, *scene.light, Options(), camera, true, LightTracer::Joins::Direct) {}
  Colour Trace(RayTree& tree, std::uint32_t root, const PixelShaft& /*shaft*/, Sampler& /*sampler*/,
               RenderStats& /*stats*/) const override {
    const Ray& ray = tree[root];
    Hit hit;
    if (scene_.Intersect(ray.start, ray.direction, hit, true) && hit.light) {
      return scene_.light->Le(-ray.direction);
    }
    return Colour(0.0);
  }
  PixelShaft::Lights ShadowLights() const override { return PixelShaft::Lights::Area; }
  int LightPathsPerRay() const override { return LightTracer::kPathsPerRay; }
  void TraceLightPaths(Camera& camera, Sampler& sampler, int count,
                       RenderStats& stats) const override {
    tracer_.Trace(camera, sampler, count, stats);
  }

 private:
  static MonteCarloOptions Options() {
    MonteCarloOptions o;
    o.walls = MonteCarloOptions::Walls::Diffuse;
    return o;
  }
  const Scene& scene_;
  LightTracer tracer_;
};

Pinhole CameraOf(const Scene& scene) {
  return Camera::GeometryFor(scene.wall, scene.camera, kSize, kSize);
}

TEST(LightTracer, AloneItSeesTheDirectlyLitSurfacesAsTheCameraDoes) {
  // Only Lambertian surfaces (the glass sphere made one too): with terminal walls the
  // camera's image is the direct light at the first surface each ray meets, Le
  // rho/pi cos cos' A / r^2 by next-event estimation; light tracing's is the same sum
  // through W_e, so W_e's every factor (D^2, the pixel's area, cos^3, cos_x / r^2) shows.
  const Scene scene = LoadScene(
      SourcePath("scenes/cornell-lambert.json"),
      {"/objects/1/material=lambertian", "/objects/1/ior=null", "/objects/1/whitted_diffuse=null",
       "/objects/1/whitted_specular=null", "/objects/1/reflectance=[0.5,0.6,0.7]"});
  const MonteCarloIntegrator camera(scene, MonteCarloOptions{});
  const LightAlone light(scene, CameraOf(scene));
  const SamplerKind random = SamplerKind::Random;
  const Image pilot = RenderWithSampler(scene, camera, random, kSize, 16, 99);
  const Image a = RenderWithSampler(scene, light, random, kSize, 256, 21);
  const Image b = RenderWithSampler(scene, light, random, kSize, 256, 22);
  const Image r1 = RenderWithSampler(scene, camera, random, kSize, 64, 11);
  const Image r2 = RenderWithSampler(scene, camera, random, kSize, 64, 12);
  ExpectAgreementWithPower("light tracing alone against next-event estimation", a, b, r1, &r2,
                           pilot);
}

// --caustics light (A, B) against off (R1, R2) on `scene` with diffuse walls and `o`'s
// other switches.
void ExpectCausticsAgree(const std::string& label, const Scene& scene, MonteCarloOptions o, int spp,
                         double minNoiseRatio) {
  o.walls = MonteCarloOptions::Walls::Diffuse;
  MonteCarloOptions light = o;
  light.caustics = MonteCarloOptions::Caustics::Light;
  const MonteCarloIntegrator off(scene, o);
  const MonteCarloIntegrator on(scene, light, CameraOf(scene));
  const SamplerKind sobol = SamplerKind::Sobol;
  const Image pilot = RenderWithSampler(scene, on, SamplerKind::Random, kSize, 16, 99);
  const Image a = RenderWithSampler(scene, on, sobol, kSize, spp, 21);
  const Image b = RenderWithSampler(scene, on, sobol, kSize, spp, 22);
  const Image r1 = RenderWithSampler(scene, off, sobol, kSize, spp, 11);
  const Image r2 = RenderWithSampler(scene, off, sobol, kSize, spp, 12);
  ExpectAgreementWithPower(label, a, b, r1, &r2, pilot);
  double noiseOn = 0.0;
  double noiseOff = 0.0;
  for (std::size_t i = 0; i < a.Pixels().size(); ++i) {
    const Colour r = 0.25 * (a.Pixels()[i] + b.Pixels()[i] + r1.Pixels()[i] + r2.Pixels()[i]);
    const Colour dOn = a.Pixels()[i] - b.Pixels()[i];
    const Colour dOff = r1.Pixels()[i] - r2.Pixels()[i];
    for (int k = 0; k < 3; ++k) {
      noiseOn += dOn[k] * dOn[k] / (r[k] * r[k] + 0.01);
      noiseOff += dOff[k] * dOff[k] / (r[k] * r[k] + 0.01);
    }
  }
  std::printf("%s: relative noise variance %.2fx lower with light tracing\n", label.c_str(),
              noiseOff / noiseOn);
  EXPECT_GT(noiseOff / noiseOn, minNoiseRatio) << label;
}

TEST(LightTracer, MirrorAndGlassCausticsAreCountedOnce) {
  const Scene scene = LoadScene(SourcePath("scenes/cornell-mirror.json"));
  ExpectCausticsAgree("mirror scene", scene, MonteCarloOptions{}, 256, 2.0);
}

TEST(LightTracer, BothStrategiesWeighTheSamePathsWhereEachMatters) {
  // In the mirror scene light tracing takes nearly all of a caustic (r = p_t1 / p_s0 in
  // the hundreds), so a light-side weight of 1 would hardly show. A light of most of the
  // ceiling and a view plane near the back wall (a narrow view: W_e large) bring r to
  // about 1 on the back wall, where dropping either side's weight counts a caustic twice.
  const Scene scene = LoadScene(
      SourcePath("scenes/cornell-mirror.json"),
      {"/area_light/side=0.8", "/area_light/radiance=[2,2,2]", "/camera/view_plane_distance=2.3"});
  ExpectCausticsAgree("large light, narrow view", scene, MonteCarloOptions{}, 256, 1.0);
}

TEST(LightTracer, GlassChosenByFresnelAndMirrorsWithoutTheirNextEventEstimation) {
  // Light paths choose at the glass as the camera's do; with --mirror-light brdf the
  // paths of one mirror are joined too.
  const Scene scene = LoadScene(SourcePath("scenes/cornell-mirror.json"));
  MonteCarloOptions o;
  o.glass = MonteCarloOptions::Glass::Choose;
  o.mirrorLight = MonteCarloOptions::MirrorLight::Brdf;
  ExpectCausticsAgree("choose, mirror light brdf", scene, o, 512, 2.0);
}

TEST(LightTracer, GlossyCausticsAreCountedOnceUnderEveryStrategy) {
  // The canonical scene's Phong spheres: a light path's first object Phong competes with
  // next-event estimation there as well as with the camera's lobe samples.
  const Scene scene = testing::CanonicalScene();
  for (const auto strategy : {MonteCarloOptions::Strategy::Mis, MonteCarloOptions::Strategy::Light,
                              MonteCarloOptions::Strategy::Brdf}) {
    MonteCarloOptions o;
    o.strategy = strategy;
    o.branches = strategy == MonteCarloOptions::Strategy::Mis ? 2 : 1;
    ExpectCausticsAgree("canonical scene, strategy " + std::to_string(static_cast<int>(strategy)),
                        scene, o, 256, 1.0);
  }
}

}  // namespace
}  // namespace glint
