// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by TerminalWallLanes at run time.
#include "glint/transport/TerminalWallLanes.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

#include "glint/core/Math.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/TerminalWallLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation, in its order (the comments name it), so that
// every lane rounds as MonteCarloIntegrator::Trace does; -ffp-contract=off keeps the
// compiler from fusing a product and a sum into one FMA.
template <class D>
void TraceWallLanesIn(D d, const WallLaneConstants& k, RayLanes& lanes, int count) {
  const std::size_t w = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    // Pinhole::DirectionThrough: v = planeCentre + (sx, sy, 0) - eye, v / |v|.
    const auto px = hn::Load(d, lanes.px.data() + i);
    const auto py = hn::Load(d, lanes.py.data() + i);
    const auto sx = hn::Sub(hn::Mul(px, hn::Set(d, k.pixelWidth)), hn::Set(d, k.halfWidth));
    const auto sy = hn::Sub(hn::Set(d, k.halfHeight), hn::Mul(py, hn::Set(d, k.pixelHeight)));
    const auto vx = hn::Sub(hn::Add(hn::Set(d, k.viewPlane[0]), sx), hn::Set(d, k.eye[0]));
    const auto vy = hn::Sub(hn::Add(hn::Set(d, k.viewPlane[1]), sy), hn::Set(d, k.eye[1]));
    const auto vz = hn::Set(d, (k.viewPlane[2] + 0.0) - k.eye[2]);
    const auto len2 = hn::Add(hn::Add(hn::Mul(vx, vx), hn::Mul(vy, vy)), hn::Mul(vz, vz));
    const auto inv = hn::Div(hn::Set(d, 1.0), hn::Sqrt(len2));  // glm::inversesqrt
    const auto dx = hn::Mul(vx, inv);
    const auto dy = hn::Mul(vy, inv);
    const auto dz = hn::Mul(vz, inv);

    // Wall::DistanceThrough: t = gap / |d[axis]|; FillHit: eye + t d on the wall's plane.
    const auto da = k.axis == 0 ? dx : (k.axis == 1 ? dy : dz);
    const auto gap = hn::IfThenElse(hn::Gt(da, zero), hn::Set(d, k.gapUp), hn::Set(d, k.gapDown));
    const auto t = hn::Div(gap, hn::Abs(da));
    const auto plane = hn::Set(d, k.plane);
    const auto ex = k.axis == 0 ? plane : hn::Add(hn::Set(d, k.eye[0]), hn::Mul(t, dx));
    const auto ey = k.axis == 1 ? plane : hn::Add(hn::Set(d, k.eye[1]), hn::Mul(t, dy));
    const auto ez = k.axis == 2 ? plane : hn::Add(hn::Set(d, k.eye[2]), hn::Mul(t, dz));

    // FacingNormal: the wall's normal, or its opposite if the ray comes from behind.
    const auto gx = hn::Set(d, k.normal[0]);
    const auto gy = hn::Set(d, k.normal[1]);
    const auto gz = hn::Set(d, k.normal[2]);
    const auto facing =
        hn::Lt(hn::Add(hn::Add(hn::Mul(dx, gx), hn::Mul(dy, gy)), hn::Mul(dz, gz)), zero);
    const auto nx = hn::IfThenElse(facing, gx, hn::Neg(gx));
    const auto ny = hn::IfThenElse(facing, gy, hn::Neg(gy));
    const auto nz = hn::IfThenElse(facing, gz, hn::Neg(gz));

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
    const auto xx = hn::Sub(yx, ex);
    const auto xy = hn::Sub(yy, ey);
    const auto xz = hn::Sub(yz, ez);
    const auto cosNumerator = hn::Add(hn::Add(hn::Mul(nx, xx), hn::Mul(ny, xy)), hn::Mul(nz, xz));
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

    hn::Store(dx, d, lanes.direction[0].data() + i);
    hn::Store(dy, d, lanes.direction[1].data() + i);
    hn::Store(dz, d, lanes.direction[2].data() + i);
    hn::Store(ex, d, lanes.end[0].data() + i);
    hn::Store(ey, d, lanes.end[1].data() + i);
    hn::Store(ez, d, lanes.end[2].data() + i);
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

namespace {
WallLaneKernel KernelFor(SimdTarget target) {
  switch (target) {
    case SimdTarget::Sse4:
      return HWY_CHOOSE_SSE4(TraceWallLanes);
    case SimdTarget::Avx2:
      return HWY_CHOOSE_AVX2(TraceWallLanes);
    case SimdTarget::Avx512:
      return HWY_CHOOSE_AVX3(TraceWallLanes);
    case SimdTarget::Auto:
    case SimdTarget::Scalar:
      break;
  }
  return &HWY_STATIC_DISPATCH(TraceWallLane);
}

std::array<double, 3> Array(vec3 v) {
  return {v.x, v.y, v.z};
}
}  // namespace

TerminalWallLanes::TerminalWallLanes(const Wall& room, const Light& light, const Pinhole& camera,
                                     SimdTarget target)
    : target_(ResolveSimdTarget(target)), width_(SimdLanes(target_)), kernel_(KernelFor(target_)) {
  if (!SimdTargetSupported(target_) || kernel_ == nullptr) {
    throw std::invalid_argument(std::string("this CPU does not run SIMD target '") +
                                SimdTargetName(target_) +
                                "'; it runs: " + SupportedSimdTargetNames());
  }
  const vec3 eye = camera.Eye();
  for (int side = 0; side < Wall::kSides; ++side) {
    WallLaneConstants& k = sides_[static_cast<std::size_t>(side)];
    k.eye = Array(eye);
    k.viewPlane = Array(camera.ViewPlaneCentre());
    k.pixelWidth = camera.PixelWidth();
    k.pixelHeight = camera.PixelHeight();
    k.halfWidth = camera.HalfWidth();
    k.halfHeight = camera.HalfHeight();
    k.axis = Wall::AxisOf(side);
    const auto a = static_cast<glm::length_t>(k.axis);
    k.gapUp = room.MaxCorner()[a] - eye[a];  // Wall::DistanceThrough's two cases
    k.gapDown = eye[a] - room.Position()[a];
    k.plane = room.PlaneOf(side);
    k.normal = Array(room.Face(side).Normal());
    const Rectangle& shape = light.Shape();
    k.lightCorner = Array(shape.Corner());
    k.lightEdgeA = Array(shape.EdgeA());
    k.lightEdgeB = Array(shape.EdgeB());
    k.lightNormal = Array(light.Normal());
    k.lightArea = light.Area();
    k.radiance = Array(light.Radiance() * room.GetMaterial(side).reflectance);
  }
}

void TerminalWallLanes::Trace(RayLanes& lanes, int count, int side) const {
  const int padded = (count + width_ - 1) / width_ * width_;
  for (int i = count; i < padded; ++i) {  // spare lanes: lane 0's numbers, results ignored
    const auto j = static_cast<std::size_t>(i);
    lanes.px[j] = lanes.px[0];
    lanes.py[j] = lanes.py[0];
    lanes.lightU[j] = lanes.lightU[0];
    lanes.lightV[j] = lanes.lightV[0];
  }
  kernel_(sides_[static_cast<std::size_t>(side)], lanes, padded);
}

}  // namespace glint
#endif  // HWY_ONCE
