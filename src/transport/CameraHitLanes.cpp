// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by CameraHitLanes at run time.
#include "glint/transport/CameraHitLanes.hpp"

#include <cstddef>

#include "glint/core/LanePadding.hpp"
#include "glint/transport/HitLanes.hpp"  // FillHitFromLane

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/CameraHitLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/CameraWallLanes-inl.h"
#include "glint/transport/ClosestHitLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation in its order (the comments name the function),
// so that every lane rounds as Scene::Intersect does; -ffp-contract=off keeps products and
// sums apart. Where the scalar code would branch on a rare case the lane is marked -1.
template <class D>
void FindHitsIn(D d, const HitLaneConstants& k, RayLanes& lanes, int count) {
  using V = hn::Vec<D>;
  const std::size_t w = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  const auto set = [d](double x) { return hn::Set(d, x); };
  const auto dot = [](V ax, V ay, V az, V bx, V by, V bz) {  // glm::dot: (x + y) + z
    return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
  };
  const auto code = [set](Scene::Closest c) { return set(static_cast<double>(c)); };
  // b = f.d and |f - b d|^2: the squared distance of a centre, at f from the eye, from
  // the ray's line (Sphere::Roots, Cube::MissesBound).
  const auto perpendicular2 = [dot](V fx, V fy, V fz, V dx, V dy, V dz, V& b) {
    b = dot(fx, fy, fz, dx, dy, dz);
    const V px = hn::Sub(fx, hn::Mul(b, dx));
    const V py = hn::Sub(fy, hn::Mul(b, dy));
    const V pz = hn::Sub(fz, hn::Mul(b, dz));
    return dot(px, py, pz, px, py, pz);
  };
  const V eye[3] = {set(k.camera.eye[0]), set(k.camera.eye[1]), set(k.camera.eye[2])};
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    CameraWallHit<V> h{};
    CameraDirection(d, k.camera, lanes.px.data() + i, lanes.py.data() + i, h);
    const V dx = h.dx;
    const V dy = h.dy;
    const V dz = h.dz;
    // IntersectSlabs' and Exit's parallel cases.
    auto rare = hn::Or(hn::Or(hn::Eq(dx, zero), hn::Eq(dy, zero)), hn::Eq(dz, zero));

    // Wall::Nearer: from inside the room, or in front of it through the opening, Exit.
    if (!k.eyeInside) {
      if (!k.eyeInFront) {
        rare = hn::Eq(zero, zero);
      } else {  // EntersThroughOpening
        const V s = set(k.frontGap);
        const V speed = hn::Neg(dz);
        const auto enters = hn::And(
            hn::And(
                hn::Lt(dz, zero),
                hn::And(hn::Ge(hn::Add(hn::Mul(set(k.toLow[0]), speed), hn::Mul(s, dx)), zero),
                        hn::Ge(hn::Sub(hn::Mul(set(k.toHigh[0]), speed), hn::Mul(s, dx)), zero))),
            hn::And(hn::Ge(hn::Add(hn::Mul(set(k.toLow[1]), speed), hn::Mul(s, dy)), zero),
                    hn::Ge(hn::Sub(hn::Mul(set(k.toHigh[1]), speed), hn::Mul(s, dy)), zero)));
        rare = hn::Or(rare, hn::Not(enters));
      }
    }
    // Wall::Exit: the axis whose face comes first, gap_b |d_a| < gap_a |d_b| (no speed
    // is 0 here), then t = gap / |d| on it.
    const V gx = hn::IfThenElse(hn::Gt(dx, zero), set(k.gapUp[0]), set(k.gapDown[0]));
    const V gy = hn::IfThenElse(hn::Gt(dy, zero), set(k.gapUp[1]), set(k.gapDown[1]));
    const V gz = hn::IfThenElse(hn::Gt(dz, zero), set(k.gapUp[2]), set(k.gapDown[2]));
    const V sx = hn::Abs(dx);
    const V sy = hn::Abs(dy);
    const V sz = hn::Abs(dz);
    const auto yFirst = hn::Lt(hn::Mul(gy, sx), hn::Mul(gx, sy));
    V gap = hn::IfThenElse(yFirst, gy, gx);
    V speed = hn::IfThenElse(yFirst, sy, sx);
    V along = hn::IfThenElse(yFirst, dy, dx);
    V axis = hn::IfThenElse(yFirst, set(1.0), zero);
    const auto zFirst = hn::Lt(hn::Mul(gz, speed), hn::Mul(gap, sz));
    gap = hn::IfThenElse(zFirst, gz, gap);
    speed = hn::IfThenElse(zFirst, sz, speed);
    along = hn::IfThenElse(zFirst, dz, along);
    axis = hn::IfThenElse(zFirst, set(2.0), axis);
    const V wallFace =
        hn::Add(hn::Add(axis, axis), hn::IfThenElse(hn::Gt(along, zero), set(1.0), zero));
    V t = hn::Div(gap, speed);
    // Out the open front (face 5), or not ahead: Scene::Intersect's rare paths.
    rare = hn::Or(rare, hn::Or(hn::Eq(wallFace, set(5.0)), hn::Not(hn::Gt(t, zero))));
    V winner = code(Scene::Closest::Wall);
    V index = zero;
    V face = wallFace;

    // Sphere::Nearer, each sphere in turn (Roots with f = eye - centre).
    ClosestSoFar<V> closest{t, winner, index, face, {zero, zero, zero}};
    const V dirs[3] = {dx, dy, dz};
    for (std::size_t s = 0; s < k.spheres.size(); ++s) {
      const HitLaneConstants::SphereTerms& c = k.spheres[s];
      V b;
      const V discriminant =
          hn::Sub(set(c.r2), perpendicular2(set(c.f[0]), set(c.f[1]), set(c.f[2]), dx, dy, dz, b));
      rare = hn::Or(rare, NearerSphere(d, b, discriminant, set(c.c), s, c.centre, closest));
    }

    // Cube::Nearer, each cube in turn: MissesBound, then IntersectSlabs (the planes' gaps
    // from the eye computed once).
    for (std::size_t s = 0; s < k.cubes.size(); ++s) {
      const HitLaneConstants::CubeTerms& c = k.cubes[s];
      V b;
      const V p2 = perpendicular2(set(c.f[0]), set(c.f[1]), set(c.f[2]), dx, dy, dz, b);
      const CubeGaps<V> gaps{c.boundRadius,
                             c.boundRadius2,
                             {set(c.low[0]), set(c.low[1]), set(c.low[2])},
                             {set(c.high[0]), set(c.high[1]), set(c.high[2])}};
      NearerCube(d, b, p2, gaps, dirs, s, closest);
    }
    t = closest.t;
    winner = closest.winner;
    index = closest.index;
    face = closest.face;

    // The light: Rectangle::Intersect below t (1 + 1e-12) + 1e-15, winning ties.
    if (k.light) {
      const V tMax = hn::Add(hn::Mul(t, set(1.0 + 1e-12)), set(1e-15));
      const V denom =
          dot(dx, dy, dz, set(k.lightNormal[0]), set(k.lightNormal[1]), set(k.lightNormal[2]));
      rare = hn::Or(rare, hn::Eq(denom, zero));
      const auto facing =
          k.lightDistance > 0.0 ? hn::Gt(denom, zero) : hn::Not(hn::Gt(denom, zero));
      const V tHit = hn::Div(set(k.lightDistance), denom);
      const V qx = hn::Sub(hn::Add(set(k.camera.eye[0]), hn::Mul(tHit, dx)), set(k.lightCorner[0]));
      const V qy = hn::Sub(hn::Add(set(k.camera.eye[1]), hn::Mul(tHit, dy)), set(k.lightCorner[1]));
      const V qz = hn::Sub(hn::Add(set(k.camera.eye[2]), hn::Mul(tHit, dz)), set(k.lightCorner[2]));
      const V u = dot(qx, qy, qz, set(k.lightInvA[0]), set(k.lightInvA[1]), set(k.lightInvA[2]));
      const V v = dot(qx, qy, qz, set(k.lightInvB[0]), set(k.lightInvB[1]), set(k.lightInvB[2]));
      constexpr double kEdgeTolerance = 1e-12;  // Rectangle::Intersect's
      const V low = set(-kEdgeTolerance);
      const V high = set(1.0 + kEdgeTolerance);
      const auto outside =
          hn::Or(hn::Or(hn::Lt(u, low), hn::Gt(u, high)), hn::Or(hn::Lt(v, low), hn::Gt(v, high)));
      const auto wins =
          hn::AndNot(outside, hn::And(facing, hn::And(hn::Gt(tHit, zero), hn::Lt(tHit, tMax))));
      t = hn::IfThenElse(wins, tHit, t);
      winner = hn::IfThenElse(wins, code(Scene::Closest::Light), winner);
    }

    hn::Store(dx, d, lanes.direction[0].data() + i);
    hn::Store(dy, d, lanes.direction[1].data() + i);
    hn::Store(dz, d, lanes.direction[2].data() + i);
    if (!k.spheres.empty()) StoreSphereNormals(d, eye, dirs, t, closest.centre, lanes, i);
    hn::Store(t, d, lanes.t.data() + i);
    hn::Store(hn::IfThenElse(rare, set(-1.0), winner), d, lanes.closest.data() + i);
    hn::Store(index, d, lanes.closestIndex.data() + i);
    hn::Store(face, d, lanes.closestFace.data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void FindHits(const HitLaneConstants& k, RayLanes& lanes, int count) {
  FindHitsIn(hn::ScalableTag<double>(), k, lanes, count);
}
void FindHitsOneLane(const HitLaneConstants& k, RayLanes& lanes, int count) {
  FindHitsIn(hn::CappedTag<double, 1>(), k, lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

namespace {

HitLaneConstants ConstantsOf(const Scene& scene, const Pinhole& camera, bool withAreaLight) {
  HitLaneConstants k;
  k.camera = CameraWallConstantsOf(scene.wall, camera, Wall::kBack);
  const vec3 o = camera.Eye();
  const Wall& room = scene.wall;
  const vec3 lo = room.Position();
  const vec3 hi = room.MaxCorner();
  k.eyeInside = room.Contains(o);
  k.eyeInFront = o.z > hi.z && o.x >= lo.x && o.x <= hi.x && o.y >= lo.y && o.y <= hi.y;
  k.frontGap = o.z - hi.z;
  k.toLow = {o.x - lo.x, o.y - lo.y};
  k.toHigh = {hi.x - o.x, hi.y - o.y};
  for (glm::length_t a = 0; a < 3; ++a) {
    k.gapUp[static_cast<std::size_t>(a)] = hi[a] - o[a];
    k.gapDown[static_cast<std::size_t>(a)] = o[a] - lo[a];
  }
  for (const Sphere& s : scene.spheres) {
    const vec3 f = o - s.Centre();
    const double r = s.Radius();
    k.spheres.push_back({LaneArray(f), glm::dot(f, f) - r * r, r * r, LaneArray(s.Centre())});
  }
  for (const Cube& c : scene.cubes) {
    HitLaneConstants::CubeTerms t{};
    t.f = LaneArray(o - c.Centre());
    t.boundRadius = c.BoundRadius();
    t.boundRadius2 = c.BoundRadius2();
    t.low = LaneArray(c.Position() - o);
    t.high = LaneArray(c.MaxCorner() - o);
    k.cubes.push_back(t);
  }
  if (withAreaLight && scene.light) {
    const Rectangle& shape = scene.light->Shape();
    k.light = true;
    k.lightCorner = LaneArray(shape.Corner());
    k.lightNormal = LaneArray(shape.Normal());
    k.lightInvA = LaneArray(shape.InvA());
    k.lightInvB = LaneArray(shape.InvB());
    k.lightDistance = glm::dot(shape.Corner() - o, shape.Normal());
  }
  return k;
}

}  // namespace

CameraHitLanes::CameraHitLanes(const Scene& scene, const Pinhole& camera, bool withAreaLight,
                               SimdTarget target)
    : scene_(scene),
      eye_(camera.Eye()),
      k_(ConstantsOf(scene, camera, withAreaLight)),
      target_(ResolveSimdTarget(target)),
      width_(SimdLanes(target_)),
      kernel_(KernelForTarget<HitLaneKernel>(target_, HWY_CHOOSE_SSE4(FindHits),
                                             HWY_CHOOSE_AVX2(FindHits), HWY_CHOOSE_AVX3(FindHits),
                                             &HWY_STATIC_DISPATCH(FindHitsOneLane))) {}

void CameraHitLanes::Trace(RayLanes& lanes, int count) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(count, width_, lanes.px, lanes.py);
  kernel_(k_, lanes, padded);
}

bool CameraHitLanes::FillHit(const RayLanes& lanes, int i, Hit& hit) const {
  return FillHitFromLane(scene_, lanes, i, eye_, hit);
}

}  // namespace glint
#endif  // HWY_ONCE
