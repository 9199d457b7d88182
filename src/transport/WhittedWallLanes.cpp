// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by WhittedWallLanes at run time.
#include "glint/transport/WhittedWallLanes.hpp"

#include <cstddef>
#include <stdexcept>

#include "glint/core/LanePadding.hpp"
#include "glint/core/Math.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/WhittedWallLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/CameraWallLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is WhittedIntegrator::LocalLight's operation for a wall (kd, no specular
// lobe), in its order, so that every lane rounds as the scalar code does; the camera ray
// and its wall: CameraWallLanes-inl.h; -ffp-contract=off keeps products and sums apart.
template <class D>
void TraceWhittedLanesIn(D d, const WhittedWallLaneConstants& k, RayLanes& lanes, int count,
                         PointLightLanes& out) {
  const std::size_t w = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    const auto h = CameraRayToWall(d, k.hit, lanes.px.data() + i, lanes.py.data() + i);
    for (std::size_t j = 0; j < static_cast<std::size_t>(k.lights); ++j) {
      // l = position - p, r^2 = l.l, l /= sqrt(r^2), cos(theta) = n.l.
      auto lx = hn::Sub(hn::Set(d, k.position[j][0]), h.ex);
      auto ly = hn::Sub(hn::Set(d, k.position[j][1]), h.ey);
      auto lz = hn::Sub(hn::Set(d, k.position[j][2]), h.ez);
      const auto r2 = hn::Add(hn::Add(hn::Mul(lx, lx), hn::Mul(ly, ly)), hn::Mul(lz, lz));
      const auto r = hn::Sqrt(r2);
      lx = hn::Div(lx, r);
      ly = hn::Div(ly, r);
      lz = hn::Div(lz, r);
      const auto cosTheta =
          hn::Add(hn::Add(hn::Mul(h.nx, lx), hn::Mul(h.ny, ly)), hn::Mul(h.nz, lz));
      // The scalar test is `<= 0: skip`: a NaN passes it, and so it does here.
      const auto behind = hn::Le(cosTheta, zero);
      const auto q = hn::Div(cosTheta, r2);  // E = I (cos(theta) / r^2)
      for (std::size_t c = 0; c < 3; ++c) {
        const auto e = hn::Mul(hn::Set(d, k.intensity[j][c]), q);
        const auto term = hn::Mul(hn::Set(d, k.diffuse[c]), e);  // (rho brdf) E
        hn::Store(hn::IfThenZeroElse(behind, term), d, out.term[j][c].data() + i);
      }
      hn::Store(hn::IfThenZeroElse(behind, hn::Set(d, 1.0)), d, out.facing[j].data() + i);
    }
    hn::Store(h.dx, d, lanes.direction[0].data() + i);
    hn::Store(h.dy, d, lanes.direction[1].data() + i);
    hn::Store(h.dz, d, lanes.direction[2].data() + i);
    hn::Store(h.ex, d, lanes.end[0].data() + i);
    hn::Store(h.ey, d, lanes.end[1].data() + i);
    hn::Store(h.ez, d, lanes.end[2].data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void TraceWhittedLanes(const WhittedWallLaneConstants& k, RayLanes& lanes, int count,
                       PointLightLanes& out) {
  TraceWhittedLanesIn(hn::ScalableTag<double>(), k, lanes, count, out);
}
void TraceWhittedLane(const WhittedWallLaneConstants& k, RayLanes& lanes, int count,
                      PointLightLanes& out) {
  TraceWhittedLanesIn(hn::CappedTag<double, 1>(), k, lanes, count, out);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

WhittedWallLanes::WhittedWallLanes(const Wall& room, const std::vector<PointLight>& lights,
                                   const Pinhole& camera, SimdTarget target)
    : target_(ResolveSimdTarget(target)),
      width_(SimdLanes(target_)),
      kernel_(KernelForTarget<WhittedLaneKernel>(
          target_, HWY_CHOOSE_SSE4(TraceWhittedLanes), HWY_CHOOSE_AVX2(TraceWhittedLanes),
          HWY_CHOOSE_AVX3(TraceWhittedLanes), &HWY_STATIC_DISPATCH(TraceWhittedLane))) {
  if (!Serves(lights))
    throw std::invalid_argument("the Whitted lanes serve at most 4 point lights");
  for (int side = 0; side < Wall::kSides; ++side) {
    WhittedWallLaneConstants& k = sides_[static_cast<std::size_t>(side)];
    k.hit = CameraWallConstantsOf(room, camera, side);
    k.lights = static_cast<int>(lights.size());
    for (std::size_t j = 0; j < lights.size(); ++j) {
      k.position[j] = LaneArray(lights[j].position);
      k.intensity[j] = LaneArray(lights[j].intensity);
    }
    const Material& m = room.GetMaterial(side);
    k.diffuse = LaneArray(m.reflectance * (m.whittedDiffuse * kInvPi));
  }
}

void WhittedWallLanes::Trace(RayLanes& lanes, int count, int side, PointLightLanes& out) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(count, width_, lanes.px, lanes.py);
  kernel_(sides_[static_cast<std::size_t>(side)], lanes, padded, out);
}

}  // namespace glint
#endif  // HWY_ONCE
