// The parts of Scene::Intersect's search that the two closest-hit kernels share
// (CameraHitLanes for rays from the eye, HitLanes for rays from any origin), in SIMD
// lanes for every Highway target: included by each kernel file's foreach_target pass
// (Highway's -inl.h convention: the guard toggles per target). Each line is the scalar
// code's operation in its order (Sphere::Roots and Nearer, Cube::MissesBound and Nearer
// with IntersectSlabs), so every lane rounds as the scalar search does; the kernels
// differ only in how they find the terms of a ray's origin (once for the eye, or per ray).
// NOLINTBEGIN(llvm-header-guard)
#if defined(GLINT_CLOSEST_HIT_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLINT_CLOSEST_HIT_LANES_INL_H_
#undef GLINT_CLOSEST_HIT_LANES_INL_H_
#else
#define GLINT_CLOSEST_HIT_LANES_INL_H_
#endif
// NOLINTEND(llvm-header-guard)

#include <hwy/highway.h>

#include <array>
#include <cstddef>

#include "glint/camera/RayLanes.hpp"

#include "glint/core/Math.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/SegmentLanes-inl.h"  // NormalizeLanes

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {

// The search so far, lane by lane: the distance t, Scene::Closest's code of what was met,
// its index among the spheres or cubes and its face, as doubles (RayLanes' form).
template <class V>
struct ClosestSoFar {
  V t, winner, index, face;
  V centre[3];  // the last sphere to win's centre
};

// Sphere::Nearer for sphere number n, centred at `centre`, from Roots' b = f.d,
// discriminant r^2 - |f - b d|^2 and c = |f|^2 - r^2: lowers t where the nearest root
// ahead is closer. Returns the lanes that Roots' rare case (q = 0) leaves to the scalar
// search.
template <class D>
HWY_INLINE hwy::HWY_NAMESPACE::Mask<D> NearerSphere(D d, hwy::HWY_NAMESPACE::Vec<D> b,
                                                    hwy::HWY_NAMESPACE::Vec<D> discriminant,
                                                    hwy::HWY_NAMESPACE::Vec<D> c, std::size_t n,
                                                    const std::array<double, 3>& centre,
                                                    ClosestSoFar<hwy::HWY_NAMESPACE::Vec<D>>& s) {
  namespace hn = hwy::HWY_NAMESPACE;
  const auto zero = hn::Zero(d);
  const auto misses = hn::Lt(discriminant, zero);
  // Stable roots: q = -(b + sign(b) sqrt(disc)), t0 = q, t1 = c / q, ordered.
  const auto q = hn::Neg(hn::Add(b, hn::CopySign(hn::Sqrt(discriminant), b)));
  const auto t0 = q;
  const auto t1 = hn::Div(c, q);
  const auto swap = hn::Gt(t0, t1);
  const auto near = hn::IfThenElse(swap, t1, t0);
  const auto far = hn::IfThenElse(swap, t0, t1);
  const auto nearest = hn::IfThenElse(hn::Gt(near, zero), near, far);
  const auto wins = hn::AndNot(misses, hn::And(hn::Gt(nearest, zero), hn::Lt(nearest, s.t)));
  s.t = hn::IfThenElse(wins, nearest, s.t);
  s.winner =
      hn::IfThenElse(wins, hn::Set(d, static_cast<double>(Scene::Closest::Sphere)), s.winner);
  s.index = hn::IfThenElse(wins, hn::Set(d, static_cast<double>(n)), s.index);
  for (std::size_t a = 0; a < 3; ++a) {
    s.centre[a] = hn::IfThenElse(wins, hn::Set(d, centre[a]), s.centre[a]);
  }
  return hn::AndNot(misses, hn::Eq(q, zero));
}

// Sphere::FillHit's outward normal, normalize(o + t d - centre), at the search's final
// distance t, for the lanes whose closest hit is a sphere (the others' are meaningless),
// stored at lanes.sphereNormal[.][i..].
template <class D>
HWY_INLINE void StoreSphereNormals(D d, const hwy::HWY_NAMESPACE::Vec<D> (&o)[3],
                                   const hwy::HWY_NAMESPACE::Vec<D> (&dir)[3],
                                   hwy::HWY_NAMESPACE::Vec<D> t,
                                   const hwy::HWY_NAMESPACE::Vec<D> (&centre)[3], RayLanes& lanes,
                                   std::size_t i) {
  namespace hn = hwy::HWY_NAMESPACE;
  using V = hn::Vec<D>;
  V v[3];
  for (std::size_t a = 0; a < 3; ++a) {
    v[a] = hn::Sub(hn::Add(o[a], hn::Mul(t, dir[a])), centre[a]);
  }
  NormalizeLanes(d, v);  // glm::normalize
  for (std::size_t a = 0; a < 3; ++a) hn::Store(v[a], d, lanes.sphereNormal[a].data() + i);
}

// The terms of cube number n that Cube::Nearer needs: its bounding sphere's radius and
// squared radius, and along each axis the gaps from the ray's origin to its low and high
// planes (low - o, high - o).
template <class V>
struct CubeGaps {
  double boundRadius, boundRadius2;
  V low[3], high[3];
};

// Cube::Nearer for cube number n, from MissesBound's b = f.d and p2 = |f - b d|^2 (f from
// the centre to the origin): the bound's early-out, then the slabs, the entry from
// outside or the exit from inside; lowers t and sets the face where the cube is closer.
template <class D>
HWY_INLINE void NearerCube(D d, hwy::HWY_NAMESPACE::Vec<D> b, hwy::HWY_NAMESPACE::Vec<D> p2,
                           const CubeGaps<hwy::HWY_NAMESPACE::Vec<D>>& c,
                           const hwy::HWY_NAMESPACE::Vec<D> (&dir)[3], std::size_t n,
                           ClosestSoFar<hwy::HWY_NAMESPACE::Vec<D>>& s) {
  namespace hn = hwy::HWY_NAMESPACE;
  using V = hn::Vec<D>;
  const V zero = hn::Zero(d);
  const V r = hn::Set(d, c.boundRadius);
  const auto missesBound =
      hn::Or(hn::Gt(p2, hn::Set(d, c.boundRadius2)),
             hn::Or(hn::Lt(hn::Add(hn::Neg(b), r), zero), hn::Gt(hn::Sub(hn::Neg(b), r), s.t)));
  V tNear = hn::Set(d, -kInfinity);
  V tFar = hn::Set(d, kInfinity);
  V nearFace = hn::Set(d, -1.0);
  V farFace = hn::Set(d, -1.0);
  for (std::size_t a = 0; a < 3; ++a) {
    const V t0 = hn::Div(c.low[a], dir[a]);
    const V t1 = hn::Div(c.high[a], dir[a]);
    const auto backward = hn::Lt(dir[a], zero);
    const V lowFace = hn::Set(d, static_cast<double>(2 * a));
    const V highFace = hn::Set(d, static_cast<double>(2 * a + 1));
    const V enter = hn::IfThenElse(backward, t1, t0);
    const V leave = hn::IfThenElse(backward, t0, t1);
    const auto later = hn::Gt(enter, tNear);
    tNear = hn::IfThenElse(later, enter, tNear);
    nearFace = hn::IfThenElse(later, hn::IfThenElse(backward, highFace, lowFace), nearFace);
    const auto sooner = hn::Lt(leave, tFar);
    tFar = hn::IfThenElse(sooner, leave, tFar);
    farFace = hn::IfThenElse(sooner, hn::IfThenElse(backward, lowFace, highFace), farFace);
  }
  // From outside the first face is the entry; from inside (a glass cube) the exit.
  const auto entering = hn::Gt(tNear, zero);
  const V tHit = hn::IfThenElse(entering, tNear, tFar);
  const auto wins = hn::AndNot(
      missesBound, hn::And(hn::Le(tNear, tFar), hn::And(hn::Gt(tHit, zero), hn::Lt(tHit, s.t))));
  s.t = hn::IfThenElse(wins, tHit, s.t);
  s.winner = hn::IfThenElse(wins, hn::Set(d, static_cast<double>(Scene::Closest::Cube)), s.winner);
  s.index = hn::IfThenElse(wins, hn::Set(d, static_cast<double>(n)), s.index);
  s.face = hn::IfThenElse(wins, hn::IfThenElse(entering, nearFace, farFace), s.face);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#endif  // the per-target guard
