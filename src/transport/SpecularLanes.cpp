// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by SpecularLanes at run time.
#include "glint/transport/SpecularLanes.hpp"

#include <cstddef>

#include "glint/core/LanePadding.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/SpecularLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/SegmentLanes-inl.h"  // SegmentDot, NormalizeLanes

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation in its order (the comments name the function);
// -ffp-contract=off keeps products and sums apart.
template <class D>
void FindSpecularLanesIn(D d, SpecularLaneData& lanes, int count) {
  using V = hn::Vec<D>;
  const std::size_t w = hn::Lanes(d);
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    V dir[3];
    V n[3];
    for (std::size_t a = 0; a < 3; ++a) {
      dir[a] = hn::Load(d, lanes.direction[a].data() + i);
      n[a] = hn::Load(d, lanes.normal[a].data() + i);
    }
    // Reflect: d - 2 (d.n) n, normalised.
    const V twice = hn::Mul(hn::Set(d, 2.0), SegmentDot(dir, n));
    V mirror[3];
    for (std::size_t a = 0; a < 3; ++a) mirror[a] = hn::Sub(dir[a], hn::Mul(twice, n[a]));
    NormalizeLanes(d, mirror);
    // CrossDielectric: from inside (cos_i < 0) the normal and the index ratio flip.
    const V ior = hn::Load(d, lanes.ior.data() + i);
    V cosI = hn::Neg(SegmentDot(dir, n));
    const auto inside = hn::Lt(cosI, zero);
    const V eta = hn::IfThenElse(inside, hn::Div(one, ior), ior);
    cosI = hn::IfThenElse(inside, hn::Neg(cosI), cosI);
    V m[3];
    for (std::size_t a = 0; a < 3; ++a) m[a] = hn::IfThenElse(inside, hn::Neg(n[a]), n[a]);
    cosI = hn::IfThenElse(hn::Lt(one, cosI), one, cosI);  // std::min(cos_i, 1)
    const V sin2T = hn::Div(hn::Sub(one, hn::Mul(cosI, cosI)), hn::Mul(eta, eta));
    const auto total = hn::Ge(sin2T, one);  // total internal reflection
    const V under = hn::Sub(one, sin2T);
    const V cosT = hn::Sqrt(hn::IfThenElse(hn::Lt(zero, under), under, zero));  // SafeSqrt
    const V etaCosI = hn::Mul(eta, cosI);
    const V rPar = hn::Div(hn::Sub(etaCosI, cosT), hn::Add(etaCosI, cosT));
    const V etaCosT = hn::Mul(eta, cosT);
    const V rPerp = hn::Div(hn::Sub(cosI, etaCosT), hn::Add(cosI, etaCosT));
    const V f = hn::Mul(hn::Set(d, 0.5), hn::Add(hn::Mul(rPar, rPar), hn::Mul(rPerp, rPerp)));
    // t = d / eta + (cos_i / eta - cos_t) n, normalised.
    const V along = hn::Sub(hn::Div(cosI, eta), cosT);
    V t[3];
    for (std::size_t a = 0; a < 3; ++a) t[a] = hn::Add(hn::Div(dir[a], eta), hn::Mul(along, m[a]));
    NormalizeLanes(d, t);
    // Index 1: undeviated, no reflection, exactly.
    const auto matched = hn::Eq(ior, one);
    for (std::size_t a = 0; a < 3; ++a) {
      hn::Store(mirror[a], d, lanes.mirror[a].data() + i);
      hn::Store(hn::IfThenElse(matched, dir[a], t[a]), d, lanes.refracted[a].data() + i);
    }
    const auto refracts = hn::Or(matched, hn::Not(total));
    hn::Store(hn::IfThenElseZero(refracts, one), d, lanes.refracts.data() + i);
    hn::Store(hn::IfThenElse(matched, zero, hn::IfThenElse(total, one, f)), d,
              lanes.reflectance.data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void FindSpecularLanes(SpecularLaneData& lanes, int count) {
  FindSpecularLanesIn(hn::ScalableTag<double>(), lanes, count);
}
void FindSpecularLane(SpecularLaneData& lanes, int count) {
  FindSpecularLanesIn(hn::CappedTag<double, 1>(), lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

SpecularLanes::SpecularLanes(SimdTarget target)
    : width_(SimdLanes(ResolveSimdTarget(target))),
      kernel_(KernelForTarget<SpecularKernel>(
          ResolveSimdTarget(target), HWY_CHOOSE_SSE4(FindSpecularLanes),
          HWY_CHOOSE_AVX2(FindSpecularLanes), HWY_CHOOSE_AVX3(FindSpecularLanes),
          &HWY_STATIC_DISPATCH(FindSpecularLane))) {}

void SpecularLanes::Find(SpecularLaneData& lanes, int count) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(count, width_, lanes.direction, lanes.normal, lanes.ior);
  kernel_(lanes, padded);
}

}  // namespace glint
#endif  // HWY_ONCE
