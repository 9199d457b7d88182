// Single-precision lanes, studied (issue #27): the camera ray to the back wall
// (CameraWallLanes-inl.h, the code glint's lanes run) in lanes of float and of double, on
// each target this CPU runs (0 scalar, 1 sse4, 2 avx2, 3 avx512). Counters: rays/s, and
// the float hit points' largest distance from the double ones against the distance a
// spawned origin is offset by (kOriginOffset (1 + |p|)): the decision is in BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "RaySets.hpp"
#include "glint/camera/Camera.hpp"
#include "glint/core/Math.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/transport/CameraWallLanes.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "bench/bench_lanes_precision.cpp"
#include <hwy/aligned_allocator.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/CameraWallLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// n camera rays (a multiple of the widest target's lanes): their wall points into e.
template <class T, class D>
void WallPointsIn(D d, const CameraWallLaneConstants& k, const T* px, const T* py, T* ex, T* ey,
                  T* ez, std::size_t n) {
  for (std::size_t i = 0; i < n; i += hn::Lanes(d)) {
    const auto h = CameraRayToWall(d, k, px + i, py + i);
    hn::Store(h.ex, d, ex + i);
    hn::Store(h.ey, d, ey + i);
    hn::Store(h.ez, d, ez + i);
  }
}
void WallPointsFloat(const CameraWallLaneConstants& k, const float* px, const float* py, float* ex,
                     float* ey, float* ez, std::size_t n) {
  WallPointsIn(hn::ScalableTag<float>(), k, px, py, ex, ey, ez, n);
}
void WallPointsDouble(const CameraWallLaneConstants& k, const double* px, const double* py,
                      double* ex, double* ey, double* ez, std::size_t n) {
  WallPointsIn(hn::ScalableTag<double>(), k, px, py, ex, ey, ez, n);
}
void WallPointsFloatLane(const CameraWallLaneConstants& k, const float* px, const float* py,
                         float* ex, float* ey, float* ez, std::size_t n) {
  WallPointsIn(hn::CappedTag<float, 1>(), k, px, py, ex, ey, ez, n);
}
void WallPointsDoubleLane(const CameraWallLaneConstants& k, const double* px, const double* py,
                          double* ex, double* ey, double* ez, std::size_t n) {
  WallPointsIn(hn::CappedTag<double, 1>(), k, px, py, ex, ey, ez, n);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint::bench {
namespace {

template <class T>
using WallPointsKernel = void (*)(const CameraWallLaneConstants&, const T*, const T*, T*, T*, T*,
                                  std::size_t);

constexpr SimdTarget kTargets[] = {SimdTarget::Scalar, SimdTarget::Sse4, SimdTarget::Avx2,
                                   SimdTarget::Avx512};

template <class T>
WallPointsKernel<T> KernelFor(SimdTarget target) {
  if constexpr (std::is_same_v<T, float>) {
    switch (target) {
      case SimdTarget::Sse4:
        return HWY_CHOOSE_SSE4(WallPointsFloat);
      case SimdTarget::Avx2:
        return HWY_CHOOSE_AVX2(WallPointsFloat);
      case SimdTarget::Avx512:
        return HWY_CHOOSE_AVX3(WallPointsFloat);
      default:
        return &HWY_STATIC_DISPATCH(WallPointsFloatLane);
    }
  } else {
    switch (target) {
      case SimdTarget::Sse4:
        return HWY_CHOOSE_SSE4(WallPointsDouble);
      case SimdTarget::Avx2:
        return HWY_CHOOSE_AVX2(WallPointsDouble);
      case SimdTarget::Avx512:
        return HWY_CHOOSE_AVX3(WallPointsDouble);
      default:
        return &HWY_STATIC_DISPATCH(WallPointsDoubleLane);
    }
  }
}

// 4096 camera rays through the middle of a 256x256 image (where it sees the back wall).
template <class T>
struct WallRays {
  static constexpr std::size_t kCount = 4096;
  // Aligned for the widest target's Load and Store.
  hwy::AlignedFreeUniquePtr<T[]> px = hwy::AllocateAligned<T>(kCount);
  hwy::AlignedFreeUniquePtr<T[]> py = hwy::AllocateAligned<T>(kCount);
  hwy::AlignedFreeUniquePtr<T[]> ex = hwy::AllocateAligned<T>(kCount);
  hwy::AlignedFreeUniquePtr<T[]> ey = hwy::AllocateAligned<T>(kCount);
  hwy::AlignedFreeUniquePtr<T[]> ez = hwy::AllocateAligned<T>(kCount);
  WallRays() {
    for (std::size_t i = 0; i < kCount; ++i) {
      px[i] = static_cast<T>(96.0 + static_cast<double>(i % 64) + 0.37);
      py[i] = static_cast<T>(96.0 + static_cast<double>(i / 64) + 0.61);
    }
  }
};

CameraWallLaneConstants BackWall() {
  const Scene& scene = CanonicalScene();
  return CameraWallConstantsOf(scene.wall, Camera::GeometryFor(scene.wall, scene.camera, 256, 256),
                               Wall::kBack);
}

// The float lanes' largest hit-point error, in units of the offset a spawned origin gets.
double FloatErrorInOffsets(const CameraWallLaneConstants& k) {
  WallRays<float> f;
  WallRays<double> d;
  KernelFor<float>(SimdTarget::Scalar)(k, f.px.get(), f.py.get(), f.ex.get(), f.ey.get(),
                                       f.ez.get(), WallRays<float>::kCount);
  KernelFor<double>(SimdTarget::Scalar)(k, d.px.get(), d.py.get(), d.ex.get(), d.ey.get(),
                                        d.ez.get(), WallRays<double>::kCount);
  double worst = 0.0;
  for (std::size_t i = 0; i < WallRays<float>::kCount; ++i) {
    const vec3 p(d.ex[i], d.ey[i], d.ez[i]);
    const double err =
        std::max({std::abs(f.ex[i] - p.x), std::abs(f.ey[i] - p.y), std::abs(f.ez[i] - p.z)});
    worst = std::max(worst, err / (kOriginOffset * (1.0 + MaxAbsComponent(p))));
  }
  return worst;
}

template <class T>
void WallPointsPrecision(benchmark::State& state) {
  const SimdTarget target = kTargets[state.range(0)];
  if (!SimdTargetSupported(target)) {
    state.SkipWithError("this CPU does not run the target");
    return;
  }
  const CameraWallLaneConstants k = BackWall();
  const WallPointsKernel<T> kernel = KernelFor<T>(target);
  WallRays<T> r;
  for (auto _ : state) {
    kernel(k, r.px.get(), r.py.get(), r.ex.get(), r.ey.get(), r.ez.get(), WallRays<T>::kCount);
    benchmark::DoNotOptimize(r.ex.get()[0]);
    benchmark::ClobberMemory();
  }
  state.SetLabel(SimdTargetName(target));
  state.counters["rays/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * WallRays<T>::kCount, benchmark::Counter::kIsRate);
  if constexpr (std::is_same_v<T, float>) state.counters["error/offset"] = FloatErrorInOffsets(k);
}
BENCHMARK(WallPointsPrecision<float>)->DenseRange(0, 3);
BENCHMARK(WallPointsPrecision<double>)->DenseRange(0, 3);

}  // namespace
}  // namespace glint::bench
#endif  // HWY_ONCE
