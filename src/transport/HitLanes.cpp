// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, dispatched by HitLanes at run time.
#include "glint/transport/HitLanes.hpp"

#include <cstddef>

#include "glint/core/LanePadding.hpp"
#include "glint/transport/CameraWallLanes.hpp"  // LaneArray

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/transport/HitLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "glint/transport/ClosestHitLanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each line is the scalar code's operation in its order (the comments name the function),
// so that every lane rounds as Scene::Intersect does; -ffp-contract=off keeps products and
// sums apart. Where the scalar code would branch on a rare case the lane is marked -1.
template <class D>
void FindSecondaryHitsIn(D d, const HitLaneScene& k, RayLanes& lanes, int count) {
  using V = hn::Vec<D>;
  using M = hn::Mask<D>;
  const std::size_t w = hn::Lanes(d);
  const V zero = hn::Zero(d);
  const V infinity = hn::Set(d, kInfinity);
  const auto set = [d](double x) { return hn::Set(d, x); };
  const auto dot = [](V ax, V ay, V az, V bx, V by, V bz) {  // glm::dot: (x + y) + z
    return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
  };
  const auto code = [set](Scene::Closest c) { return set(static_cast<double>(c)); };
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    const V o[3] = {hn::Load(d, lanes.start[0].data() + i), hn::Load(d, lanes.start[1].data() + i),
                    hn::Load(d, lanes.start[2].data() + i)};
    const V dir[3] = {hn::Load(d, lanes.direction[0].data() + i),
                      hn::Load(d, lanes.direction[1].data() + i),
                      hn::Load(d, lanes.direction[2].data() + i)};
    // IntersectSlabs' and Exit's parallel cases.
    M rare = hn::Or(hn::Or(hn::Eq(dir[0], zero), hn::Eq(dir[1], zero)), hn::Eq(dir[2], zero));

    // Wall::Nearer from inside the room (Contains): Exit. From outside: Scene::Intersect.
    V gap[3];
    V speed[3];
    for (std::size_t a = 0; a < 3; ++a) {
      const V lo = set(k.roomLow[a]);
      const V hi = set(k.roomHigh[a]);
      rare = hn::Or(rare, hn::Not(hn::And(hn::Ge(o[a], lo), hn::Le(o[a], hi))));
      gap[a] = hn::IfThenElse(hn::Gt(dir[a], zero), hn::Sub(hi, o[a]), hn::Sub(o[a], lo));
      speed[a] = hn::Abs(dir[a]);
    }
    // Wall::Exit: the axis whose face comes first, gap_b |d_a| < gap_a |d_b| (no speed
    // is 0 here), then t = gap / |d| on it.
    const auto yFirst = hn::Lt(hn::Mul(gap[1], speed[0]), hn::Mul(gap[0], speed[1]));
    V g = hn::IfThenElse(yFirst, gap[1], gap[0]);
    V s = hn::IfThenElse(yFirst, speed[1], speed[0]);
    V along = hn::IfThenElse(yFirst, dir[1], dir[0]);
    V axis = hn::IfThenElse(yFirst, set(1.0), zero);
    const auto zFirst = hn::Lt(hn::Mul(gap[2], s), hn::Mul(g, speed[2]));
    g = hn::IfThenElse(zFirst, gap[2], g);
    s = hn::IfThenElse(zFirst, speed[2], s);
    along = hn::IfThenElse(zFirst, dir[2], along);
    axis = hn::IfThenElse(zFirst, set(2.0), axis);
    V face = hn::Add(hn::Add(axis, axis), hn::IfThenElse(hn::Gt(along, zero), set(1.0), zero));
    const V tWall = hn::Div(g, s);
    // Out the open front (face 5), or not in (0, infinity): no wall.
    const auto wallHit =
        hn::And(hn::Ne(face, set(5.0)), hn::And(hn::Gt(tWall, zero), hn::Lt(tWall, infinity)));
    V t = hn::IfThenElse(wallHit, tWall, infinity);
    V winner = hn::IfThenElse(wallHit, code(Scene::Closest::Wall), code(Scene::Closest::None));
    V index = zero;

    // f = o - centre, b = f.d and |f - b d|^2 (Sphere::Roots, Cube::MissesBound).
    const auto perpendicular2 = [&](const std::array<double, 3>& centre, V& fx, V& fy, V& fz,
                                    V& b) {
      fx = hn::Sub(o[0], set(centre[0]));
      fy = hn::Sub(o[1], set(centre[1]));
      fz = hn::Sub(o[2], set(centre[2]));
      b = dot(fx, fy, fz, dir[0], dir[1], dir[2]);
      const V px = hn::Sub(fx, hn::Mul(b, dir[0]));
      const V py = hn::Sub(fy, hn::Mul(b, dir[1]));
      const V pz = hn::Sub(fz, hn::Mul(b, dir[2]));
      return dot(px, py, pz, px, py, pz);
    };

    // Sphere::Nearer, each sphere in turn.
    ClosestSoFar<V> closest{t, winner, index, face, {zero, zero, zero}};
    for (std::size_t n = 0; n < k.spheres.size(); ++n) {
      const HitLaneScene::SphereTerms& c = k.spheres[n];
      V fx, fy, fz, b;
      const V r2 = set(c.r2);
      const V discriminant = hn::Sub(r2, perpendicular2(c.centre, fx, fy, fz, b));
      const V cc = hn::Sub(dot(fx, fy, fz, fx, fy, fz), r2);
      rare = hn::Or(rare, NearerSphere(d, b, discriminant, cc, n, c.centre, closest));
    }

    // Cube::Nearer, each cube in turn: MissesBound, then IntersectSlabs.
    for (std::size_t n = 0; n < k.cubes.size(); ++n) {
      const HitLaneScene::CubeTerms& c = k.cubes[n];
      V fx, fy, fz, b;
      const V p2 = perpendicular2(c.centre, fx, fy, fz, b);
      CubeGaps<V> gaps{c.boundRadius, c.boundRadius2, {}, {}};
      for (std::size_t a = 0; a < 3; ++a) {
        gaps.low[a] = hn::Sub(set(c.low[a]), o[a]);
        gaps.high[a] = hn::Sub(set(c.high[a]), o[a]);
      }
      NearerCube(d, b, p2, gaps, dir, n, closest);
    }
    t = closest.t;
    winner = closest.winner;
    index = closest.index;
    face = closest.face;

    // The light: Rectangle::Intersect below t (1 + 1e-12) + 1e-15 (anything when nothing
    // else was met), winning ties.
    if (k.light) {
      const auto found = hn::Ne(winner, code(Scene::Closest::None));
      const V tMax =
          hn::IfThenElse(found, hn::Add(hn::Mul(t, set(1.0 + 1e-12)), set(1e-15)), infinity);
      const V nx = set(k.lightNormal[0]);
      const V ny = set(k.lightNormal[1]);
      const V nz = set(k.lightNormal[2]);
      const V denom = dot(dir[0], dir[1], dir[2], nx, ny, nz);
      const V distance =
          dot(hn::Sub(set(k.lightCorner[0]), o[0]), hn::Sub(set(k.lightCorner[1]), o[1]),
              hn::Sub(set(k.lightCorner[2]), o[2]), nx, ny, nz);
      const auto ahead = hn::Gt(distance, zero);
      const auto towards = hn::Gt(denom, zero);
      const auto facing = hn::Or(hn::And(ahead, towards), hn::Not(hn::Or(ahead, towards)));
      const V tHit = hn::Div(distance, denom);
      const V qx = hn::Sub(hn::Add(o[0], hn::Mul(tHit, dir[0])), set(k.lightCorner[0]));
      const V qy = hn::Sub(hn::Add(o[1], hn::Mul(tHit, dir[1])), set(k.lightCorner[1]));
      const V qz = hn::Sub(hn::Add(o[2], hn::Mul(tHit, dir[2])), set(k.lightCorner[2]));
      const V u = dot(qx, qy, qz, set(k.lightInvA[0]), set(k.lightInvA[1]), set(k.lightInvA[2]));
      const V v = dot(qx, qy, qz, set(k.lightInvB[0]), set(k.lightInvB[1]), set(k.lightInvB[2]));
      constexpr double kEdgeTolerance = 1e-12;  // Rectangle::Intersect's
      const V low = set(-kEdgeTolerance);
      const V high = set(1.0 + kEdgeTolerance);
      const auto outside =
          hn::Or(hn::Or(hn::Lt(u, low), hn::Gt(u, high)), hn::Or(hn::Lt(v, low), hn::Gt(v, high)));
      const auto wins =
          hn::AndNot(outside, hn::And(hn::And(facing, hn::Ne(denom, zero)),
                                      hn::And(hn::Gt(tHit, zero), hn::Lt(tHit, tMax))));
      t = hn::IfThenElse(wins, tHit, t);
      winner = hn::IfThenElse(wins, code(Scene::Closest::Light), winner);
    }

    if (!k.spheres.empty()) StoreSphereNormals(d, o, dir, t, closest.centre, lanes, i);
    hn::Store(t, d, lanes.t.data() + i);
    hn::Store(hn::IfThenElse(rare, set(-1.0), winner), d, lanes.closest.data() + i);
    hn::Store(index, d, lanes.closestIndex.data() + i);
    hn::Store(face, d, lanes.closestFace.data() + i);
  }
}

// The target's full width, and one lane (the scalar path: the same code).
void FindSecondaryHits(const HitLaneScene& k, RayLanes& lanes, int count) {
  FindSecondaryHitsIn(hn::ScalableTag<double>(), k, lanes, count);
}
void FindSecondaryHitsOneLane(const HitLaneScene& k, RayLanes& lanes, int count) {
  FindSecondaryHitsIn(hn::CappedTag<double, 1>(), k, lanes, count);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

namespace {

HitLaneScene TermsOf(const Scene& scene, bool withAreaLight) {
  HitLaneScene k;
  k.roomLow = LaneArray(scene.wall.Position());
  k.roomHigh = LaneArray(scene.wall.MaxCorner());
  for (const Sphere& s : scene.spheres) {
    k.spheres.push_back({LaneArray(s.Centre()), s.Radius() * s.Radius()});
  }
  for (const Cube& c : scene.cubes) {
    k.cubes.push_back({LaneArray(c.Centre()), LaneArray(c.Position()), LaneArray(c.MaxCorner()),
                       c.BoundRadius(), c.BoundRadius2()});
  }
  if (withAreaLight && scene.light) {
    const Rectangle& shape = scene.light->Shape();
    k.light = true;
    k.lightCorner = LaneArray(shape.Corner());
    k.lightNormal = LaneArray(shape.Normal());
    k.lightInvA = LaneArray(shape.InvA());
    k.lightInvB = LaneArray(shape.InvB());
  }
  return k;
}

}  // namespace

HitLanes::HitLanes(const Scene& scene, bool withAreaLight, SimdTarget target)
    : scene_(scene),
      k_(TermsOf(scene, withAreaLight)),
      width_(SimdLanes(ResolveSimdTarget(target))),
      kernel_(KernelForTarget<SecondaryHitKernel>(
          ResolveSimdTarget(target), HWY_CHOOSE_SSE4(FindSecondaryHits),
          HWY_CHOOSE_AVX2(FindSecondaryHits), HWY_CHOOSE_AVX3(FindSecondaryHits),
          &HWY_STATIC_DISPATCH(FindSecondaryHitsOneLane))) {}

void HitLanes::Trace(RayLanes& lanes, int count) const {
  // Spare lanes: lane 0's inputs, results ignored.
  const int padded = PadLanesFromLaneZero(count, width_, lanes.start, lanes.direction);
  kernel_(k_, lanes, padded);
}

bool FillHitFromLane(const Scene& scene, const RayLanes& lanes, int i, vec3 origin, Hit& hit) {
  const auto j = static_cast<std::size_t>(i);
  const auto winner = static_cast<Scene::Closest>(static_cast<int>(lanes.closest[j]));
  const int index = static_cast<int>(lanes.closestIndex[j]);
  int face = static_cast<int>(lanes.closestFace[j]);
  if (winner == Scene::Closest::Sphere) {  // its normal from the lanes
    scene.spheres[static_cast<std::size_t>(index)].FillHitAt(
        vec3(lanes.sphereNormal[0][j], lanes.sphereNormal[1][j], lanes.sphereNormal[2][j]),
        lanes.t[j], hit);
    return true;
  }
  if (winner == Scene::Closest::Wall) face = Wall::SideOfFace(face);
  const vec3 direction(lanes.direction[0][j], lanes.direction[1][j], lanes.direction[2][j]);
  return scene.FillClosest(winner, index, face, lanes.t[j], origin, direction, hit);
}

bool HitLanes::FillHit(const RayLanes& lanes, int i, Hit& hit) const {
  const auto j = static_cast<std::size_t>(i);
  return FillHitFromLane(scene_, lanes, i,
                         vec3(lanes.start[0][j], lanes.start[1][j], lanes.start[2][j]), hit);
}

}  // namespace glint
#endif  // HWY_ONCE
