// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by LocalLightLanes at run time.
#include "glint/transport/LocalLightLanes.hpp"

#include <algorithm>
#include <cstddef>

#include "glint/core/LanePadding.hpp"
#include "glint/transport/CameraWallLanes.hpp"  // LaneArray

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/LocalLightLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/sampling/CosinePowerLanes-inl.h"
#include "glint/transport/SegmentLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation in its order (the comments name the function),
// so that every lane rounds as WhittedIntegrator::LocalLight does; -ffp-contract=off keeps
// products and sums apart.
template <class D>
void ShadeLocalLightLanesIn(D d, const LocalLightLaneScene& scene, LocalLightLaneData& lanes,
                            int count) {
  using V = hn::Vec<D>;
  using M = hn::Mask<D>;
  const std::size_t w = hn::Lanes(d);
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  const auto set = [d](double x) { return hn::Set(d, x); };
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    V p[3];
    V n[3];
    V ray[3];
    for (std::size_t a = 0; a < 3; ++a) {
      p[a] = hn::Load(d, lanes.point[a].data() + i);
      n[a] = hn::Load(d, lanes.normal[a].data() + i);
      ray[a] = hn::Load(d, lanes.direction[a].data() + i);
    }
    const M hasSpecular = hn::Ne(hn::Load(d, lanes.specular.data() + i), zero);
    const bool specular = !hn::AllFalse(d, hasSpecular);
    const V exponent = hn::Load(d, lanes.exponent.data() + i);
    const V offset = OriginOffset(d, p);
    V sum[3] = {zero, zero, zero};
    V shadowRays = zero;
    for (const LocalLightLaneScene::LightTerms& light : scene.lights) {
      // l = position - p, r^2 = l.l, l /= sqrt(r^2), cos(theta) = n.l.
      V l[3];
      for (std::size_t a = 0; a < 3; ++a) l[a] = hn::Sub(set(light.position[a]), p[a]);
      const V r2 = SegmentDot(l, l);
      const V r = hn::Sqrt(r2);
      for (V& c : l) c = hn::Div(c, r);
      const V cosTheta = SegmentDot(n, l);
      // The scalar test is `<= 0: skip`: a NaN passes it, and so it does here.
      const M cast = hn::Not(hn::Le(cosTheta, zero));
      shadowRays = hn::Add(shadowRays, hn::IfThenElseZero(cast, one));
      // Reaches: from OffsetRayOrigin(p, n, l) to the light, v = q - origin.
      const M along = hn::Ge(SegmentDot(l, n), zero);
      V o[3];
      OffsetRayOriginLanes<D>(p, n, offset, along, o);
      V v[3];
      for (std::size_t a = 0; a < 3; ++a) v[a] = hn::Sub(set(light.position[a]), o[a]);
      const M blocked = SegmentBlocked(d, scene.segments, o, v);
      // brdf = kd / pi, plus ks (n + 2) / (2 pi) CosinePower(max(0, Reflect(-l, n) . -d), n).
      V brdf = hn::Load(d, lanes.diffuse.data() + i);
      if (specular) {
        const V negL[3] = {hn::Neg(l[0]), hn::Neg(l[1]), hn::Neg(l[2])};
        const V twice = hn::Mul(set(2.0), SegmentDot(negL, n));  // 2 dot(-l, n)
        V rd[3];
        for (std::size_t a = 0; a < 3; ++a) rd[a] = hn::Sub(negL[a], hn::Mul(twice, n[a]));
        const V negRay[3] = {hn::Neg(ray[0]), hn::Neg(ray[1]), hn::Neg(ray[2])};
        const V towardsEye = SegmentDot(rd, negRay);
        const V cosR =
            hn::IfThenElse(hn::Lt(zero, towardsEye), towardsEye, zero);  // std::max(0, .)
        const V power = CosinePowerLanes(d, cosR, exponent, scene.exponentBits);
        const V lobe = hn::Mul(hn::Load(d, lanes.specularScale.data() + i), power);
        brdf = hn::IfThenElse(hasSpecular, hn::Add(brdf, lobe), brdf);
      }
      // E = I (cos(theta) / r^2); sum += (rho brdf) E, for a lane that casts and is not blocked.
      const M lit = hn::AndNot(blocked, cast);
      const V e = hn::Div(cosTheta, r2);
      for (std::size_t c = 0; c < 3; ++c) {
        const V term = hn::Mul(hn::Mul(hn::Load(d, lanes.reflectance[c].data() + i), brdf),
                               hn::Mul(set(light.intensity[c]), e));
        sum[c] = hn::IfThenElse(lit, hn::Add(sum[c], term), sum[c]);
      }
    }
    for (std::size_t c = 0; c < 3; ++c) hn::Store(sum[c], d, lanes.colour[c].data() + i);
    hn::Store(shadowRays, d, lanes.shadowRays.data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void ShadeLocalLightLanes(const LocalLightLaneScene& k, LocalLightLaneData& lanes, int count) {
  ShadeLocalLightLanesIn(hn::ScalableTag<double>(), k, lanes, count);
}
void ShadeLocalLightLane(const LocalLightLaneScene& k, LocalLightLaneData& lanes, int count) {
  ShadeLocalLightLanesIn(hn::CappedTag<double, 1>(), k, lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

namespace {

LocalLightLaneScene TermsOf(const Scene& scene) {
  LocalLightLaneScene k;
  for (const PointLight& light : scene.pointLights) {
    k.lights.push_back({LaneArray(light.position), LaneArray(light.intensity)});
  }
  k.segments = SegmentLaneScene::Of(scene, /*glassBlocks=*/false);  // through glass
  // Enough squarings for every exponent the lanes may be given: up to 1024, 11 bits.
  double largest = 0.0;
  const auto take = [&largest](const Material& m) {
    if (m.whittedSpecular > 0.0 && LocalLightLanes::Serves(m))
      largest = std::max(largest, m.exponent);
  };
  for (const Sphere& s : scene.spheres) take(s.GetMaterial());
  for (const Cube& c : scene.cubes) take(c.GetMaterial());
  for (int side = 0; side < Wall::kSides; ++side) take(scene.wall.GetMaterial(side));
  while (static_cast<double>(1 << k.exponentBits) <= largest) ++k.exponentBits;
  return k;
}

}  // namespace

LocalLightLanes::LocalLightLanes(const Scene& scene, SimdTarget target)
    : k_(TermsOf(scene)),
      width_(SimdLanes(ResolveSimdTarget(target))),
      kernel_(KernelForTarget<LocalLightKernel>(
          ResolveSimdTarget(target), HWY_CHOOSE_SSE4(ShadeLocalLightLanes),
          HWY_CHOOSE_AVX2(ShadeLocalLightLanes), HWY_CHOOSE_AVX3(ShadeLocalLightLanes),
          &HWY_STATIC_DISPATCH(ShadeLocalLightLane))) {}

void LocalLightLanes::SetMaterial(LocalLightLaneData& lanes, std::size_t j, const Material& m) {
  for (std::size_t c = 0; c < 3; ++c)
    lanes.reflectance[c][j] = m.reflectance[static_cast<glm::length_t>(c)];
  lanes.diffuse[j] = m.whittedDiffuse * kInvPi;
  const bool specular = m.whittedSpecular > 0.0;
  lanes.specular[j] = specular ? 1.0 : 0.0;
  lanes.specularScale[j] = specular ? m.whittedSpecular * (m.exponent + 2.0) / (2.0 * kPi) : 0.0;
  lanes.exponent[j] = specular ? m.exponent : 0.0;
}

void LocalLightLanes::Shade(LocalLightLaneData& lanes, int count) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(count, width_, lanes.point, lanes.normal, lanes.direction,
                                          lanes.reflectance, lanes.diffuse, lanes.specularScale,
                                          lanes.exponent, lanes.specular);
  kernel_(k_, lanes, padded);
}

}  // namespace glint
#endif  // HWY_ONCE
