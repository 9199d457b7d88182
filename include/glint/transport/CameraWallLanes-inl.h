// The camera ray to a roomOnly pixel's wall in SIMD lanes, for every Highway target:
// included by each kernel file's foreach_target pass (Highway's -inl.h convention: the
// guard toggles per target). Each line is the scalar code's operation in its order
// (Pinhole::DirectionThrough, Wall::DistanceThrough and FillHit, FacingNormal), so every
// lane rounds as the scalar path does; -ffp-contract=off keeps products and sums apart.
// NOLINTBEGIN(llvm-header-guard)
#if defined(GLINT_CAMERA_WALL_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GLINT_CAMERA_WALL_LANES_INL_H_
#undef GLINT_CAMERA_WALL_LANES_INL_H_
#else
#define GLINT_CAMERA_WALL_LANES_INL_H_
#endif
// NOLINTEND(llvm-header-guard)

#include <hwy/highway.h>

#include "glint/transport/CameraWallLanes.hpp"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {

// Where W camera rays went: unit direction d, the wall point e, the normal n facing d.
template <class V>
struct CameraWallHit {
  V dx, dy, dz, ex, ey, ez, nx, ny, nz;
};

// Pinhole::DirectionThrough in lanes: the unit direction through image points (px, py),
// into h.dx, h.dy, h.dz.
template <class D>
HWY_INLINE void CameraDirection(D d, const CameraWallLaneConstants& k,
                                const hwy::HWY_NAMESPACE::TFromD<D>* pxIn,
                                const hwy::HWY_NAMESPACE::TFromD<D>* pyIn,
                                CameraWallHit<hwy::HWY_NAMESPACE::Vec<D>>& h) {
  namespace hn = hwy::HWY_NAMESPACE;
  using T = hn::TFromD<D>;
  const auto set = [d](double x) { return hn::Set(d, static_cast<T>(x)); };
  // v = planeCentre + (sx, sy, 0) - eye, v / |v|.
  const auto px = hn::Load(d, pxIn);
  const auto py = hn::Load(d, pyIn);
  const auto sx = hn::Sub(hn::Mul(px, set(k.pixelWidth)), set(k.halfWidth));
  const auto sy = hn::Sub(set(k.halfHeight), hn::Mul(py, set(k.pixelHeight)));
  const auto vx = hn::Sub(hn::Add(set(k.viewPlane[0]), sx), set(k.eye[0]));
  const auto vy = hn::Sub(hn::Add(set(k.viewPlane[1]), sy), set(k.eye[1]));
  const auto vz = set((k.viewPlane[2] + 0.0) - k.eye[2]);
  const auto len2 = hn::Add(hn::Add(hn::Mul(vx, vx), hn::Mul(vy, vy)), hn::Mul(vz, vz));
  const auto inv = hn::Div(set(1.0), hn::Sqrt(len2));  // glm::inversesqrt
  h.dx = hn::Mul(vx, inv);
  h.dy = hn::Mul(vy, inv);
  h.dz = hn::Mul(vz, inv);
}

// Lanes of double (glint's) or of float (the single-precision study, bench_lanes_precision).
template <class D>
HWY_INLINE CameraWallHit<hwy::HWY_NAMESPACE::Vec<D>> CameraRayToWall(
    D d, const CameraWallLaneConstants& k, const hwy::HWY_NAMESPACE::TFromD<D>* pxIn,
    const hwy::HWY_NAMESPACE::TFromD<D>* pyIn) {
  namespace hn = hwy::HWY_NAMESPACE;
  using T = hn::TFromD<D>;
  const auto set = [d](double x) { return hn::Set(d, static_cast<T>(x)); };
  const auto zero = hn::Zero(d);
  CameraWallHit<hn::Vec<D>> h{};
  CameraDirection(d, k, pxIn, pyIn, h);

  // Wall::DistanceThrough: t = gap / |d[axis]|; FillHit: eye + t d on the wall's plane.
  const auto da = k.axis == 0 ? h.dx : (k.axis == 1 ? h.dy : h.dz);
  const auto gap = hn::IfThenElse(hn::Gt(da, zero), set(k.gapUp), set(k.gapDown));
  const auto t = hn::Div(gap, hn::Abs(da));
  const auto plane = set(k.plane);
  h.ex = k.axis == 0 ? plane : hn::Add(set(k.eye[0]), hn::Mul(t, h.dx));
  h.ey = k.axis == 1 ? plane : hn::Add(set(k.eye[1]), hn::Mul(t, h.dy));
  h.ez = k.axis == 2 ? plane : hn::Add(set(k.eye[2]), hn::Mul(t, h.dz));

  // FacingNormal: the wall's normal, or its opposite if the ray comes from behind.
  const auto gx = set(k.normal[0]);
  const auto gy = set(k.normal[1]);
  const auto gz = set(k.normal[2]);
  const auto facing =
      hn::Lt(hn::Add(hn::Add(hn::Mul(h.dx, gx), hn::Mul(h.dy, gy)), hn::Mul(h.dz, gz)), zero);
  h.nx = hn::IfThenElse(facing, gx, hn::Neg(gx));
  h.ny = hn::IfThenElse(facing, gy, hn::Neg(gy));
  h.nz = hn::IfThenElse(facing, gz, hn::Neg(gz));
  return h;
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#endif  // GLINT_CAMERA_WALL_LANES_INL_H_
