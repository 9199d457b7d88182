// The first hit of a pixel's camera rays in SIMD lanes, for the pixels the integrator's
// other lanes leave (with terminal walls those whose rays may meet an object, not
// PixelShaft::roomOnly; with diffuse walls every pixel): the camera direction and
// Scene::Intersect's closest-hit search (the room's exit, each sphere, each cube, the
// area light), lane by lane with the scalar code's operations in its order, so that each
// ray's distance and winner are the scalar ones to the bit. The integrator then shades
// each ray from that hit (Integrator::TraceFromLane). A lane whose ray takes one of the
// scalar code's rare branches (a direction component exactly 0, a ray that does not
// enter through the opening, a sphere's q = 0, a ray parallel to the light) is left to
// Scene::Intersect.
#pragma once

#include <array>
#include <vector>

#include "glint/camera/Pinhole.hpp"
#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/CameraWallLanes.hpp"

namespace glint {

// The scene's numbers the lanes need, each computed as the scalar code computes it from
// the eye (the camera rays' common origin).
struct HitLaneConstants {
  CameraWallLaneConstants camera;  // its pinhole part (the wall part is unused)
  // Wall::Nearer from the eye: whether the eye is inside the room or in front of the
  // opening; EntersThroughOpening's terms; Exit's gaps for d > 0 and d <= 0 per axis.
  bool eyeInside = false;
  bool eyeInFront = false;
  double frontGap = 0.0;                    // o.z - hi.z
  std::array<double, 2> toLow{}, toHigh{};  // o - lo, hi - o, in x and y
  std::array<double, 3> gapUp{}, gapDown{};
  struct SphereTerms {
    std::array<double, 3> f;  // eye - centre
    double c;                 // dot(f, f) - r^2
    double r2;                // r^2
    std::array<double, 3> centre;
  };
  std::vector<SphereTerms> spheres;
  struct CubeTerms {
    std::array<double, 3> f;  // eye - centre
    double boundRadius, boundRadius2;
    std::array<double, 3> low, high;  // lo - eye, hi - eye
  };
  std::vector<CubeTerms> cubes;
  bool light = false;
  std::array<double, 3> lightCorner{}, lightNormal{}, lightInvA{}, lightInvB{};
  double lightDistance = 0.0;  // dot(corner - eye, normal)
};

using HitLaneKernel = void (*)(const HitLaneConstants&, RayLanes&, int);

class CameraHitLanes {
 public:
  // The lanes for `scene` (its area light counted if `withAreaLight`) seen by `camera`, on
  // `target` (Auto: the widest the CPU runs); throws std::invalid_argument naming the
  // targets the CPU runs if it lacks `target`.
  CameraHitLanes(const Scene& scene, const Pinhole& camera, bool withAreaLight, SimdTarget target);

  // Whether the lanes pay for a pass of `rays` rays of a pixel: from 4 lanes (AVX2 and
  // AVX-512) and 8 rays. Measured (BENCHMARKS.md, "SIMD lanes"): in Monte Carlo mode the
  // scalar lane loses 5% and SSE4 gains nothing; AVX-512 at Whitted's 4 rays loses 3.5%.
  bool Pays(int rays) const { return PaysFrom(rays, 8); }
  // The same from `fewest` rays: Whitted takes them from 4, its trees then running a level
  // at a time (1.25x at its default 4 rays a pixel, BENCHMARKS.md, "SIMD lanes").
  bool PaysFrom(int rays, int fewest) const { return width_ >= 4 && rays >= fewest; }
  SimdTarget Target() const { return target_; }
  // Lanes [0, count) from their px, py: direction, and t, closest, closestIndex and
  // closestFace (RayLanes).
  void Trace(RayLanes& lanes, int count) const;
  // Lane i's hit record, as Scene::Intersect gives it for that ray; false if it met
  // nothing. The lane must have closest >= 0.
  bool FillHit(const RayLanes& lanes, int i, Hit& hit) const;
  // Lane i's hit, filled into `storage`, or null for a lane handed back to
  // Scene::Intersect (closest < 0): what the integrators' trace node takes as `known`.
  const Hit* Known(const RayLanes& lanes, int i, Hit& storage) const {
    if (lanes.closest[static_cast<std::size_t>(i)] < 0.0) return nullptr;
    FillHit(lanes, i, storage);
    return &storage;
  }

 private:
  const Scene& scene_;
  vec3 eye_;
  HitLaneConstants k_;
  SimdTarget target_;  // resolved
  int width_;
  HitLaneKernel kernel_;
};

}  // namespace glint
