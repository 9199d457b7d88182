// float or double? The same ray-sphere and ray-box tests, written once as templates,
// run in both precisions on the camera rays: the measurement behind glint's choice of
// double (see BENCHMARKS.md).
#include <benchmark/benchmark.h>

#include "RaySets.hpp"

namespace glint::bench {
namespace {

template <typename T>
struct Rays {
  std::vector<glm::vec<3, T>> origins, directions;
};

template <typename T>
const Rays<T>& CameraRaysIn() {
  static const Rays<T> rays = [] {
    const RaySet r = CameraRays(CanonicalScene());
    Rays<T> out;
    for (std::size_t i = 0; i < r.Size(); ++i) {
      out.origins.emplace_back(r.origins[i]);
      out.directions.emplace_back(r.directions[i]);
    }
    return out;
  }();
  return rays;
}

// The sphere's nearest positive root, as Sphere::Roots computes it.
template <typename T>
T SphereT(glm::vec<3, T> o, glm::vec<3, T> d, glm::vec<3, T> c, T r) {
  const glm::vec<3, T> f = o - c;
  const T b = glm::dot(f, d);
  const glm::vec<3, T> perp = f - b * d;
  const T disc = r * r - glm::dot(perp, perp);
  if (disc < T(0)) return T(-1);
  const T q = -(b + std::copysign(std::sqrt(disc), b));
  const T t0 = q;
  const T t1 = (glm::dot(f, f) - r * r) / q;
  return std::min(t0, t1) > T(0) ? std::min(t0, t1) : std::max(t0, t1);
}

// Slab test of an axis-aligned box: entry distance, or -1 for a miss.
template <typename T>
T BoxT(glm::vec<3, T> o, glm::vec<3, T> invD, glm::vec<3, T> lo, glm::vec<3, T> hi) {
  const glm::vec<3, T> a = (lo - o) * invD;
  const glm::vec<3, T> b = (hi - o) * invD;
  const glm::vec<3, T> near = glm::min(a, b);
  const glm::vec<3, T> far = glm::max(a, b);
  const T tNear = std::max({near.x, near.y, near.z});
  const T tFar = std::min({far.x, far.y, far.z});
  return tNear <= tFar && tFar > T(0) ? tNear : T(-1);
}

template <typename T>
void SpherePrecision(benchmark::State& state) {
  const Rays<T>& r = CameraRaysIn<T>();
  const glm::vec<3, T> c(0.22, 0.18, 0.40);
  T sum = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < r.origins.size(); ++i)
      sum += SphereT<T>(r.origins[i], r.directions[i], c, T(0.18));
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * r.origins.size()));
}
BENCHMARK(SpherePrecision<float>);
BENCHMARK(SpherePrecision<double>);

template <typename T>
void BoxPrecision(benchmark::State& state) {
  const Rays<T>& r = CameraRaysIn<T>();
  const glm::vec<3, T> lo(0.42, 0.0, 0.06);
  const glm::vec<3, T> hi(0.70, 0.28, 0.34);
  T sum = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < r.origins.size(); ++i)
      sum += BoxT<T>(r.origins[i], T(1) / r.directions[i], lo, hi);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * r.origins.size()));
}
BENCHMARK(BoxPrecision<float>);
BENCHMARK(BoxPrecision<double>);

}  // namespace
}  // namespace glint::bench
