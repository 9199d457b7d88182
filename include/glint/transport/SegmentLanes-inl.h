// Scene::Blocked's test of a shadow segment from o to o + v, in SIMD lanes for every
// Highway target: included by each kernel file's foreach_target pass (Highway's -inl.h
// convention: the guard toggles per target). Each line is the scalar code's operation in
// its order (Sphere::IntersectsSegment, Cube::IntersectsSegment with IntersectSlabs), so
// every lane decides as the scalar test does; -ffp-contract=off keeps products and sums apart.
// NOLINTBEGIN(llvm-header-guard)
#if defined(GLINT_SEGMENT_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLINT_SEGMENT_LANES_INL_H_
#undef GLINT_SEGMENT_LANES_INL_H_
#else
#define GLINT_SEGMENT_LANES_INL_H_
#endif
// NOLINTEND(llvm-header-guard)

#include <hwy/highway.h>

#include <array>
#include <cstddef>

#include "glint/core/Math.hpp"
#include "glint/transport/SegmentLanes.hpp"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {

// glm::dot's order: (x + y) + z.
template <class V>
V SegmentDot(const V* a, const V* b) {
  namespace hn = hwy::HWY_NAMESPACE;
  return hn::Add(hn::Add(hn::Mul(a[0], b[0]), hn::Mul(a[1], b[1])), hn::Mul(a[2], b[2]));
}

// OffsetRayOrigin's distance from p, kOriginOffset (1 + max |p_a|): where a shadow
// segment starts.
template <class D>
hwy::HWY_NAMESPACE::Vec<D> OriginOffset(D d, const hwy::HWY_NAMESPACE::Vec<D>* p) {
  namespace hn = hwy::HWY_NAMESPACE;
  return hn::Mul(
      hn::Set(d, kOriginOffset),
      hn::Add(hn::Set(d, 1.0), hn::Max(hn::Max(hn::Abs(p[0]), hn::Abs(p[1])), hn::Abs(p[2]))));
}

// glm::normalize's v * inversesqrt(v.v), as 1 / sqrt(v.v) (glm::inversesqrt), in place.
template <class D>
void NormalizeLanes(D d, hwy::HWY_NAMESPACE::Vec<D>* v) {
  namespace hn = hwy::HWY_NAMESPACE;
  const hn::Vec<D> inv = hn::Div(hn::Set(d, 1.0), hn::Sqrt(SegmentDot(v, v)));
  for (int a = 0; a < 3; ++a) v[a] = hn::Mul(v[a], inv);
}

// OffsetRayOrigin(p, n, w) from its distance `offset` (OriginOffset): p + offset n where
// `outward` (w.n >= 0), else p - offset n.
template <class D>
void OffsetRayOriginLanes(const hwy::HWY_NAMESPACE::Vec<D>* p, const hwy::HWY_NAMESPACE::Vec<D>* n,
                          hwy::HWY_NAMESPACE::Vec<D> offset, hwy::HWY_NAMESPACE::Mask<D> outward,
                          hwy::HWY_NAMESPACE::Vec<D>* origin) {
  namespace hn = hwy::HWY_NAMESPACE;
  for (int a = 0; a < 3; ++a) {
    const hn::Vec<D> step = hn::Mul(offset, n[a]);
    origin[a] = hn::IfThenElse(outward, hn::Add(p[a], step), hn::Sub(p[a], step));
  }
}

// Both tests' start: f = o - centre, b = f.v and q = a f - b v, a = v.v (whose length
// is a times the distance from the centre to the segment's line).
template <class V>
struct SegmentToCentre {
  V f[3];
  V b;
  V q[3];
};
template <class D>
SegmentToCentre<hwy::HWY_NAMESPACE::Vec<D>> ToCentre(D d, const std::array<double, 3>& centre,
                                                     const hwy::HWY_NAMESPACE::Vec<D>* o,
                                                     const hwy::HWY_NAMESPACE::Vec<D>* v,
                                                     hwy::HWY_NAMESPACE::Vec<D> va) {
  namespace hn = hwy::HWY_NAMESPACE;
  SegmentToCentre<hn::Vec<D>> t;
  for (std::size_t a = 0; a < 3; ++a) t.f[a] = hn::Sub(o[a], hn::Set(d, centre[a]));
  t.b = SegmentDot(t.f, v);
  for (std::size_t a = 0; a < 3; ++a) t.q[a] = hn::Sub(hn::Mul(va, t.f[a]), hn::Mul(t.b, v[a]));
  return t;
}

// Sphere::IntersectsSegment: whether the points o + s v, s in (0, 1), meet the sphere;
// va = v.v.
template <class D>
hwy::HWY_NAMESPACE::Mask<D> SphereMeetsSegment(D d, const SegmentLaneScene::SphereTerms& s,
                                               const hwy::HWY_NAMESPACE::Vec<D>* o,
                                               const hwy::HWY_NAMESPACE::Vec<D>* v,
                                               hwy::HWY_NAMESPACE::Vec<D> va) {
  namespace hn = hwy::HWY_NAMESPACE;
  using V = hn::Vec<D>;
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  const SegmentToCentre<V> t = ToCentre(d, s.centre, o, v, va);
  const V* f = t.f;
  const V* q = t.q;
  const V b = t.b;
  const V r2a = hn::Set(d, s.r2);
  const V scaled = hn::Sub(hn::Mul(hn::Mul(r2a, va), va), SegmentDot(q, q));
  const auto misses = hn::Or(hn::Lt(scaled, zero), hn::Eq(va, zero));
  const V c = hn::Sub(SegmentDot(f, f), r2a);
  const V root = hn::Neg(hn::Add(b, hn::CopySign(hn::Sqrt(hn::Div(scaled, va)), b)));
  const V s0 = hn::Div(root, va);
  const V s1 = hn::Div(c, root);
  const auto inside0 = hn::And(hn::Gt(s0, zero), hn::Lt(s0, one));
  const auto inside1 = hn::And(hn::Gt(s1, zero), hn::Lt(s1, one));
  return hn::AndNot(hn::Or(misses, hn::Eq(root, zero)), hn::Or(inside0, inside1));
}

// Cube::IntersectsSegment: the bound, then IntersectSlabs along v.
template <class D>
hwy::HWY_NAMESPACE::Mask<D> CubeMeetsSegment(D d, const SegmentLaneScene::CubeTerms& c,
                                             const hwy::HWY_NAMESPACE::Vec<D>* o,
                                             const hwy::HWY_NAMESPACE::Vec<D>* v,
                                             hwy::HWY_NAMESPACE::Vec<D> va) {
  namespace hn = hwy::HWY_NAMESPACE;
  using V = hn::Vec<D>;
  using M = hn::Mask<D>;
  const V zero = hn::Zero(d);
  const V one = hn::Set(d, 1.0);
  const SegmentToCentre<V> t = ToCentre(d, c.centre, o, v, va);
  const M outsideBound =
      hn::Gt(SegmentDot(t.q, t.q), hn::Mul(hn::Mul(hn::Set(d, c.boundRadius2), va), va));
  V tNear = hn::Set(d, -kInfinity);
  V tFar = hn::Set(d, kInfinity);
  M missesSlab = hn::Lt(one, zero);  // none
  for (std::size_t a = 0; a < 3; ++a) {
    const V lo = hn::Set(d, c.low[a]);
    const V hi = hn::Set(d, c.high[a]);
    // Parallel to the slab: inside it for all s, or never.
    const M parallel = hn::Eq(v[a], zero);
    missesSlab = hn::Or(missesSlab, hn::And(parallel, hn::Or(hn::Lt(o[a], lo), hn::Gt(o[a], hi))));
    const V t0 = hn::Div(hn::Sub(lo, o[a]), v[a]);
    const V t1 = hn::Div(hn::Sub(hi, o[a]), v[a]);
    const M backward = hn::Lt(v[a], zero);
    const V enter = hn::IfThenElse(backward, t1, t0);
    const V leave = hn::IfThenElse(backward, t0, t1);
    tNear = hn::IfThenElse(hn::AndNot(parallel, hn::Gt(enter, tNear)), enter, tNear);
    tFar = hn::IfThenElse(hn::AndNot(parallel, hn::Lt(leave, tFar)), leave, tFar);
  }
  const M nearInside = hn::And(hn::Gt(tNear, zero), hn::Lt(tNear, one));
  const M farInside = hn::And(hn::Gt(tFar, zero), hn::Lt(tFar, one));
  return hn::AndNot(hn::Or(outsideBound, missesSlab),
                    hn::And(hn::Le(tNear, tFar), hn::Or(nearInside, farInside)));
}

// Scene::Blocked(o, o + v): whether any of the scene's spheres or cubes meets the segment.
template <class D>
hwy::HWY_NAMESPACE::Mask<D> SegmentBlocked(D d, const SegmentLaneScene& scene,
                                           const hwy::HWY_NAMESPACE::Vec<D>* o,
                                           const hwy::HWY_NAMESPACE::Vec<D>* v) {
  namespace hn = hwy::HWY_NAMESPACE;
  const auto va = SegmentDot(v, v);                     // a = v.v
  auto blocked = hn::Lt(hn::Set(d, 1.0), hn::Zero(d));  // none
  for (const SegmentLaneScene::SphereTerms& s : scene.spheres) {
    blocked = hn::Or(blocked, SphereMeetsSegment(d, s, o, v, va));
  }
  for (const SegmentLaneScene::CubeTerms& c : scene.cubes) {
    blocked = hn::Or(blocked, CubeMeetsSegment(d, c, o, v, va));
  }
  return blocked;
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#endif  // GLINT_SEGMENT_LANES_INL_H_
