// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by TerminalWallLanes at run time.
#include "glint/transport/TerminalWallLanes.hpp"

#include <cstddef>

#include "glint/core/LanePadding.hpp"
#include "glint/core/Math.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/TerminalWallLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/CameraWallLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation, in its order (the comments name it), so that
// every lane rounds as MonteCarloIntegrator::Trace does (the camera ray and its wall:
// CameraWallLanes-inl.h); -ffp-contract=off keeps products and sums apart.
template <class D>
void TraceWallLanesIn(D d, const WallLaneConstants& k, RayLanes& lanes, int count) {
  const std::size_t w = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    const auto h = CameraRayToWall(d, k.hit, lanes.px.data() + i, lanes.py.data() + i);

    // DirectLightLambertian: y = corner + u a + v b, x = y - p,
    // Le (rho / pi) (n.x) (-n_y.x) A / r^4.
    const auto u = hn::Load(d, lanes.lightU.data() + i);
    const auto v = hn::Load(d, lanes.lightV.data() + i);
    const auto yx =
        hn::Add(hn::Add(hn::Set(d, k.lightCorner[0]), hn::Mul(u, hn::Set(d, k.lightEdgeA[0]))),
                hn::Mul(v, hn::Set(d, k.lightEdgeB[0])));
    const auto yy =
        hn::Add(hn::Add(hn::Set(d, k.lightCorner[1]), hn::Mul(u, hn::Set(d, k.lightEdgeA[1]))),
                hn::Mul(v, hn::Set(d, k.lightEdgeB[1])));
    const auto yz =
        hn::Add(hn::Add(hn::Set(d, k.lightCorner[2]), hn::Mul(u, hn::Set(d, k.lightEdgeA[2]))),
                hn::Mul(v, hn::Set(d, k.lightEdgeB[2])));
    const auto xx = hn::Sub(yx, h.ex);
    const auto xy = hn::Sub(yy, h.ey);
    const auto xz = hn::Sub(yz, h.ez);
    const auto cosNumerator =
        hn::Add(hn::Add(hn::Mul(h.nx, xx), hn::Mul(h.ny, xy)), hn::Mul(h.nz, xz));
    const auto cosLightNumerator =
        hn::Neg(hn::Add(hn::Add(hn::Mul(hn::Set(d, k.lightNormal[0]), xx),
                                hn::Mul(hn::Set(d, k.lightNormal[1]), xy)),
                        hn::Mul(hn::Set(d, k.lightNormal[2]), xz)));
    // The scalar test is `<= 0, return 0`: a NaN passes it, and so it does here.
    const auto unlit = hn::Or(hn::Le(cosNumerator, zero), hn::Le(cosLightNumerator, zero));
    const auto r2 = hn::Add(hn::Add(hn::Mul(xx, xx), hn::Mul(xy, xy)), hn::Mul(xz, xz));
    const auto geometry =
        hn::Div(hn::Mul(hn::Mul(cosNumerator, cosLightNumerator), hn::Set(d, k.lightArea)),
                hn::Mul(r2, r2));
    const auto scale = hn::Mul(hn::Set(d, kInvPi), geometry);

    hn::Store(h.dx, d, lanes.direction[0].data() + i);
    hn::Store(h.dy, d, lanes.direction[1].data() + i);
    hn::Store(h.dz, d, lanes.direction[2].data() + i);
    hn::Store(h.ex, d, lanes.end[0].data() + i);
    hn::Store(h.ey, d, lanes.end[1].data() + i);
    hn::Store(h.ez, d, lanes.end[2].data() + i);
    hn::Store(yx, d, lanes.lightPoint[0].data() + i);
    hn::Store(yy, d, lanes.lightPoint[1].data() + i);
    hn::Store(yz, d, lanes.lightPoint[2].data() + i);
    for (std::size_t c = 0; c < 3; ++c) {
      const auto colour = hn::IfThenZeroElse(unlit, hn::Mul(hn::Set(d, k.radiance[c]), scale));
      hn::Store(colour, d, lanes.colour[c].data() + i);
    }
    hn::Store(hn::IfThenZeroElse(unlit, hn::Set(d, 1.0)), d, lanes.lit.data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void TraceWallLanes(const WallLaneConstants& k, RayLanes& lanes, int count) {
  TraceWallLanesIn(hn::ScalableTag<double>(), k, lanes, count);
}
void TraceWallLane(const WallLaneConstants& k, RayLanes& lanes, int count) {
  TraceWallLanesIn(hn::CappedTag<double, 1>(), k, lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

TerminalWallLanes::TerminalWallLanes(const Wall& room, const Light& light, const Pinhole& camera,
                                     SimdTarget target)
    : target_(ResolveSimdTarget(target)),
      width_(SimdLanes(target_)),
      kernel_(KernelForTarget<WallLaneKernel>(
          target_, HWY_CHOOSE_SSE4(TraceWallLanes), HWY_CHOOSE_AVX2(TraceWallLanes),
          HWY_CHOOSE_AVX3(TraceWallLanes), &HWY_STATIC_DISPATCH(TraceWallLane))) {
  for (int side = 0; side < Wall::kSides; ++side) {
    WallLaneConstants& k = sides_[static_cast<std::size_t>(side)];
    k.hit = CameraWallConstantsOf(room, camera, side);
    const Rectangle& shape = light.Shape();
    k.lightCorner = LaneArray(shape.Corner());
    k.lightEdgeA = LaneArray(shape.EdgeA());
    k.lightEdgeB = LaneArray(shape.EdgeB());
    k.lightNormal = LaneArray(light.Normal());
    k.lightArea = light.Area();
    k.radiance = LaneArray(light.Radiance() * room.GetMaterial(side).reflectance);
  }
}

void TerminalWallLanes::Trace(RayLanes& lanes, int count, int side) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded =
      PadLanesFromLaneZero(count, width_, lanes.px, lanes.py, lanes.lightU, lanes.lightV);
  kernel_(sides_[static_cast<std::size_t>(side)], lanes, padded);
}

}  // namespace glint
#endif  // HWY_ONCE
