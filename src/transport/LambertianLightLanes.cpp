// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by LambertianLightLanes at run time.
#include "glint/transport/LambertianLightLanes.hpp"

#include <cstddef>

#include "glint/core/LanePadding.hpp"
#include "glint/core/Math.hpp"
#include "glint/transport/CameraWallLanes.hpp"  // LaneArray

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/LambertianLightLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/SegmentLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation in its order (MonteCarloIntegrator::
// DirectLightLambertian, ShadowBlocked with OffsetRayOrigin and Scene::Occluded);
// -ffp-contract=off keeps products and sums apart.
template <class D>
void EstimateLambertianLightLanesIn(D d, const LambertianLightLaneScene& k,
                                    LambertianLightLaneData& lanes, int count) {
  using V = hn::Vec<D>;
  const std::size_t w = hn::Lanes(d);
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    V p[3];
    V n[3];
    for (std::size_t a = 0; a < 3; ++a) {
      p[a] = hn::Load(d, lanes.point[a].data() + i);
      n[a] = hn::Load(d, lanes.normal[a].data() + i);
    }
    // y = corner + u a + v b (Rectangle::PointFromUV), x = y - p.
    const V u = hn::Load(d, lanes.u.data() + i);
    const V v = hn::Load(d, lanes.v.data() + i);
    V y[3];
    V x[3];
    for (std::size_t a = 0; a < 3; ++a) {
      y[a] = hn::Add(hn::Add(hn::Set(d, k.corner[a]), hn::Mul(u, hn::Set(d, k.edgeA[a]))),
                     hn::Mul(v, hn::Set(d, k.edgeB[a])));
      x[a] = hn::Sub(y[a], p[a]);
    }
    const V cosNumerator = SegmentDot(n, x);
    const V lightNormal[3] = {hn::Set(d, k.normal[0]), hn::Set(d, k.normal[1]),
                              hn::Set(d, k.normal[2])};
    const V cosLightNumerator = hn::Neg(SegmentDot(lightNormal, x));
    // The scalar test is `<= 0, return 0`: a NaN passes it, and so it does here.
    const auto cast = hn::Not(hn::Or(hn::Le(cosNumerator, zero), hn::Le(cosLightNumerator, zero)));
    const auto untested = hn::Ne(hn::Load(d, lanes.unoccluded.data() + i), zero);
    auto lit = cast;
    if (!hn::AllFalse(d, hn::AndNot(untested, cast))) {
      // OffsetRayOrigin(p, n, x): dot(x, n) >= 0 where a ray is cast, so p + d n; then
      // Scene::Occluded(origin, y), the segment v = y - origin.
      const V offset = OriginOffset(d, p);
      V o[3];
      V segment[3];
      for (std::size_t a = 0; a < 3; ++a) {
        o[a] = hn::Add(p[a], hn::Mul(offset, n[a]));
        segment[a] = hn::Sub(y[a], o[a]);
      }
      lit = hn::AndNot(hn::AndNot(untested, SegmentBlocked(d, k.blockers, o, segment)), cast);
    }
    // Le rho (1 / pi) (cos numerator) (cos_y numerator) A / r^4.
    const V r2 = SegmentDot(x, x);
    const V geometry = hn::Div(
        hn::Mul(hn::Mul(cosNumerator, cosLightNumerator), hn::Set(d, k.area)), hn::Mul(r2, r2));
    const V scale = hn::Mul(hn::Set(d, kInvPi), geometry);
    for (std::size_t c = 0; c < 3; ++c) {
      const V colour = hn::Mul(hn::Load(d, lanes.radiance[c].data() + i), scale);
      hn::Store(hn::IfThenElseZero(lit, colour), d, lanes.colour[c].data() + i);
    }
    hn::Store(hn::IfThenElseZero(cast, one), d, lanes.cast.data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void EstimateLambertianLightLanes(const LambertianLightLaneScene& k, LambertianLightLaneData& lanes,
                                  int count) {
  EstimateLambertianLightLanesIn(hn::ScalableTag<double>(), k, lanes, count);
}
void EstimateLambertianLightLane(const LambertianLightLaneScene& k, LambertianLightLaneData& lanes,
                                 int count) {
  EstimateLambertianLightLanesIn(hn::CappedTag<double, 1>(), k, lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

LambertianLightLanes::LambertianLightLanes(const Scene& scene, const Light& light,
                                           SimdTarget target)
    : k_{LaneArray(light.Shape().Corner()),
         LaneArray(light.Shape().EdgeA()),
         LaneArray(light.Shape().EdgeB()),
         LaneArray(light.Normal()),
         light.Area(),
         SegmentLaneScene::Of(scene, /*glassBlocks=*/true)},
      width_(SimdLanes(ResolveSimdTarget(target))),
      kernel_(KernelForTarget<LambertianLightKernel>(
          ResolveSimdTarget(target), HWY_CHOOSE_SSE4(EstimateLambertianLightLanes),
          HWY_CHOOSE_AVX2(EstimateLambertianLightLanes),
          HWY_CHOOSE_AVX3(EstimateLambertianLightLanes),
          &HWY_STATIC_DISPATCH(EstimateLambertianLightLane))) {}

void LambertianLightLaneData::Add(std::uint32_t index, vec3 p, vec3 n, Colour leRho, Sample2 uv,
                                  bool shaftAnswered) {
  const auto j = static_cast<std::size_t>(count++);
  for (std::size_t a = 0; a < 3; ++a) {
    const auto c = static_cast<glm::length_t>(a);
    point[a][j] = p[c];
    normal[a][j] = n[c];
    radiance[a][j] = leRho[c];
  }
  u[j] = uv.u;
  v[j] = uv.v;
  unoccluded[j] = shaftAnswered ? 1.0 : 0.0;
  node[j] = index;
}

void LambertianLightLanes::Estimate(LambertianLightLaneData& lanes) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(lanes.count, width_, lanes.point, lanes.normal,
                                          lanes.radiance, lanes.u, lanes.v, lanes.unoccluded);
  kernel_(k_, lanes, padded);
}

}  // namespace glint
#endif  // HWY_ONCE
