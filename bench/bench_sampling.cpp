// The sampling routines of Monte Carlo mode: the random generator, the Phong lobe and
// its BRDF and density, cosine sampling, and light sampling from the first hits.
#include <benchmark/benchmark.h>

#include "RaySets.hpp"
#include "glint/sampling/Sampler.hpp"
#include "glint/transport/MirroredLight.hpp"
#include "glint/transport/Phong.hpp"
#include "glint/transport/SphereReflection.hpp"

namespace glint::bench {
namespace {

// The generator's own chain (state -> state): a running sum here would time the
// floating-point additions instead.
void RngUniform(benchmark::State& state) {
  Pcg32 rng(1, 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(rng.Uniform());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(RngUniform);

void RngForPixel(benchmark::State& state) {
  std::uint64_t pixel = 0;
  for (auto _ : state) {
    Pcg32 rng = Pcg32::ForPixel(1, pixel++, 0);
    benchmark::DoNotOptimize(rng);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(RngForPixel);

// One terminal wall's path of numbers, per sample: the pixel point and the light point
// (dimensions 0-3), for each sampler; arg 0 random, 1 stratified, 2 sobol.
void SamplerTerminalPath(benchmark::State& state) {
  const auto kind = static_cast<SamplerKind>(state.range(0));
  Sampler sampler(kind, 1, 7, 0, 0, 64);
  int i = 0;
  for (auto _ : state) {
    sampler.StartSample(i++ & 63);
    benchmark::DoNotOptimize(sampler.Get2D(SampleDimension::kPixel));
    benchmark::DoNotOptimize(sampler.Get2D(SampleDimension::Light(0)));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(SamplerName(kind));
}
BENCHMARK(SamplerTerminalPath)->Arg(0)->Arg(1)->Arg(2);

// A pixel's sampler for one pass (sobol makes its first groups' seeds here).
void SamplerForPixel(benchmark::State& state) {
  const auto kind = static_cast<SamplerKind>(state.range(0));
  std::uint64_t pixel = 0;
  for (auto _ : state) {
    Sampler sampler(kind, 1, pixel++, 0, 0, 64);
    benchmark::DoNotOptimize(sampler);
  }
  state.SetLabel(SamplerName(kind));
}
BENCHMARK(SamplerForPixel)->Arg(0)->Arg(1)->Arg(2);

const Material& O1() {
  return CanonicalScene().spheres[0].GetMaterial();
}  // Phong n = 100

void SamplePhongLobe(benchmark::State& state) {
  Pcg32 rng(1, 1);
  const vec3 n(0.0, 1.0, 0.0);
  const vec3 d = glm::normalize(vec3(0.3, -1.0, -0.2));
  for (auto _ : state) {
    const PhongSample s = SamplePhong(O1(), d, n, rng.Uniform(), rng.Uniform());
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(SamplePhongLobe);

void PhongBrdfAndPdf(benchmark::State& state) {
  Pcg32 rng(1, 1);
  const vec3 n(0.0, 1.0, 0.0);
  const vec3 d = glm::normalize(vec3(0.3, -1.0, -0.2));
  for (auto _ : state) {
    const vec3 psi = Frame::FromZ(n).ToWorld(SampleCosineHemisphere(rng.Uniform(), rng.Uniform()));
    benchmark::DoNotOptimize(PhongBrdf(O1(), d, n, psi));
    benchmark::DoNotOptimize(PhongPdf(O1(), d, n, psi));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(PhongBrdfAndPdf);

void CosineHemisphere(benchmark::State& state) {
  Pcg32 rng(1, 1);
  const Frame frame = Frame::FromZ(glm::normalize(vec3(0.2, 0.9, 0.1)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(frame.ToWorld(SampleCosineHemisphere(rng.Uniform(), rng.Uniform())));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(CosineHemisphere);

void LightSampleLi(benchmark::State& state) {
  const Light& light = *CanonicalScene().light;
  const RaySet& points = []() -> const RaySet& {
    static const RaySet set = ShadowRays(CanonicalScene());
    return set;
  }();
  Pcg32 rng(1, 1);
  std::size_t i = 0;
  for (auto _ : state) {
    const LightSample s = light.SampleLi(points.origins[i], rng.Uniform(), rng.Uniform());
    benchmark::DoNotOptimize(s);
    i = i + 1 == points.Size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(LightSampleLi);

// The light seen in the mirrors of the mirror scene, from the first hits of camera rays
// that land on its walls (hit points and normals kept in ShadowRays' origins and
// directions): the sphere's reflection point alone, and the whole estimate with its
// shadow segments.
const Scene& MirrorScene() {
  static const Scene scene =
      LoadScene(std::string(GLINT_SOURCE_DIR) + "/scenes/cornell-mirror.json");
  return scene;
}
const RaySet& MirrorScenePoints() {
  static const RaySet set = FromFirstHits(
      MirrorScene(), kRays, 4, [](vec3 p, vec3 n, Pcg32&, RaySet& out) { out.Add(p, n, 0.0); });
  return set;
}

void ReflectOffMirrorSphere(benchmark::State& state) {
  const Sphere& sphere = MirrorScene().spheres[0];  // O1
  const Light& light = *MirrorScene().light;
  const RaySet& points = MirrorScenePoints();
  Pcg32 rng(1, 1);
  std::size_t i = 0;
  for (auto _ : state) {
    const vec3 y = light.SamplePoint(rng.Uniform(), rng.Uniform());
    benchmark::DoNotOptimize(
        ReflectOffSphere(sphere.Centre(), sphere.Radius(), points.origins[i], y));
    i = i + 1 == points.Size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(ReflectOffMirrorSphere);

void MirroredLightIrradiance(benchmark::State& state) {
  const MirroredLight mirrored(MirrorScene(), *MirrorScene().light);
  const RaySet& points = MirrorScenePoints();
  Pcg32 rng(1, 1);
  RenderStats stats;
  std::size_t i = 0;
  for (auto _ : state) {
    const double u = rng.Uniform();
    benchmark::DoNotOptimize(
        mirrored.Irradiance(points.origins[i], points.directions[i], u, rng.Uniform(), stats));
    i = i + 1 == points.Size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["segments"] =
      static_cast<double>(stats.shadowRays) / static_cast<double>(state.iterations());
}
BENCHMARK(MirroredLightIrradiance);

}  // namespace
}  // namespace glint::bench
