// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by LambertianScatterLanes at run time.
#include "glint/transport/LambertianScatterLanes.hpp"

#include <cstddef>

#include "glint/core/LanePadding.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/LambertianScatterLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/core/SinCosLanes-inl.h"
#include "glint/transport/SegmentLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation in its order (SampleCosineHemisphere,
// Frame::FromZ and ToWorld, glm::normalize, OffsetRayOrigin); -ffp-contract=off keeps
// products and sums apart.
template <class D>
void SampleLambertianScatterLanesIn(D d, LambertianScatterLaneData& lanes, int count) {
  using V = hn::Vec<D>;
  const std::size_t w = hn::Lanes(d);
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    V p[3];
    V normal[3];
    V n[3];
    for (std::size_t a = 0; a < 3; ++a) {
      p[a] = hn::Load(d, lanes.point[a].data() + i);
      normal[a] = hn::Load(d, lanes.normal[a].data() + i);
      n[a] = hn::Load(d, lanes.facing[a].data() + i);
    }
    // Malley's method: (r cos phi, r sin phi, SafeSqrt(1 - u)), r = sqrt(u), phi = 2 pi v.
    const V u = hn::Load(d, lanes.u.data() + i);
    const V r = hn::Sqrt(u);
    const SinCosLanes<V> phi = SinCosTurnsLanes(d, hn::Load(d, lanes.v.data() + i));
    const V lx = hn::Mul(r, phi.cos);
    const V ly = hn::Mul(r, phi.sin);
    const V c2 = hn::Sub(one, u);
    const V lz = hn::Sqrt(hn::IfThenElse(hn::Lt(zero, c2), c2, zero));  // std::max(0, c2)
    // Frame::FromZ(n) (Duff et al.): s = (1 + sign nx nx a, sign b, -sign nx),
    // t = (b, sign + ny ny a, -ny), a = -1 / (sign + nz), b = nx ny a.
    const V sign = hn::CopySign(one, n[2]);
    const V fa = hn::Div(hn::Set(d, -1.0), hn::Add(sign, n[2]));
    const V fb = hn::Mul(hn::Mul(n[0], n[1]), fa);
    const V s[3] = {hn::Add(one, hn::Mul(hn::Mul(hn::Mul(sign, n[0]), n[0]), fa)),
                    hn::Mul(sign, fb), hn::Mul(hn::Neg(sign), n[0])};
    const V t[3] = {fb, hn::Add(sign, hn::Mul(hn::Mul(n[1], n[1]), fa)), hn::Neg(n[1])};
    // ToWorld: (x s + y t) + z n, then times 1 / sqrt(w.w) (glm::inversesqrt).
    V world[3];
    for (std::size_t a = 0; a < 3; ++a) {
      world[a] = hn::Add(hn::Add(hn::Mul(lx, s[a]), hn::Mul(ly, t[a])), hn::Mul(lz, n[a]));
    }
    NormalizeLanes(d, world);
    // OffsetRayOrigin(p, normal, dir): p + o normal where dir.normal >= 0, else p - o normal.
    V start[3];
    OffsetRayOriginLanes<D>(p, normal, OriginOffset(d, p), hn::Ge(SegmentDot(world, normal), zero),
                            start);
    for (std::size_t a = 0; a < 3; ++a) {
      hn::Store(world[a], d, lanes.direction[a].data() + i);
      hn::Store(start[a], d, lanes.start[a].data() + i);
    }
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void SampleLambertianScatterLanes(LambertianScatterLaneData& lanes, int count) {
  SampleLambertianScatterLanesIn(hn::ScalableTag<double>(), lanes, count);
}
void SampleLambertianScatterLane(LambertianScatterLaneData& lanes, int count) {
  SampleLambertianScatterLanesIn(hn::CappedTag<double, 1>(), lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

LambertianScatterLanes::LambertianScatterLanes(SimdTarget target)
    : width_(SimdLanes(ResolveSimdTarget(target))),
      kernel_(KernelForTarget<LambertianScatterKernel>(
          ResolveSimdTarget(target), HWY_CHOOSE_SSE4(SampleLambertianScatterLanes),
          HWY_CHOOSE_AVX2(SampleLambertianScatterLanes),
          HWY_CHOOSE_AVX3(SampleLambertianScatterLanes),
          &HWY_STATIC_DISPATCH(SampleLambertianScatterLane))) {}

void LambertianScatterLaneData::Stage(vec3 p, vec3 surfaceNormal, vec3 facingNormal, Sample2 uv) {
  const auto j = static_cast<std::size_t>(count);
  for (std::size_t a = 0; a < 3; ++a) {
    const auto c = static_cast<glm::length_t>(a);
    point[a][j] = p[c];
    normal[a][j] = surfaceNormal[c];
    facing[a][j] = facingNormal[c];
  }
  u[j] = uv.u;
  v[j] = uv.v;
}

void LambertianScatterLanes::Sample(LambertianScatterLaneData& lanes) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(lanes.count, width_, lanes.point, lanes.normal,
                                          lanes.facing, lanes.u, lanes.v);
  kernel_(lanes, padded);
}

}  // namespace glint
#endif  // HWY_ONCE
