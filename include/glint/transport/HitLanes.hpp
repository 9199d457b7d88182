// The closest hit of rays from any origin inside the room in SIMD lanes: Scene::Intersect's
// search (the room's exit, each sphere, each cube, the area light) lane by lane, with the
// scalar code's operations in its order, so that each ray's distance and winner are the
// scalar ones to the bit. CameraHitLanes is its special case for rays from the eye, whose
// terms it computes once; these lanes compute them per ray, for the rays an integrator
// spawns (mirror and glass children, diffuse bounces). A lane whose ray takes one of the
// scalar code's rare branches (an origin outside the room, a direction component exactly
// 0, a sphere's q = 0) is left to Scene::Intersect.
#pragma once

#include <array>
#include <vector>

#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/scene/Scene.hpp"

namespace glint {

// The scene's numbers the lanes need, each as the scalar code holds it.
struct HitLaneScene {
  std::array<double, 3> roomLow{}, roomHigh{};  // Wall::Position(), MaxCorner()
  struct SphereTerms {
    std::array<double, 3> centre;
    double r2;  // radius * radius
  };
  std::vector<SphereTerms> spheres;
  struct CubeTerms {
    std::array<double, 3> centre, low, high;
    double boundRadius, boundRadius2;
  };
  std::vector<CubeTerms> cubes;
  bool light = false;
  std::array<double, 3> lightCorner{}, lightNormal{}, lightInvA{}, lightInvB{};
};

using SecondaryHitKernel = void (*)(const HitLaneScene&, RayLanes&, int);

// Lane i's hit record from a closest-hit kernel's output (HitLanes, CameraHitLanes), for
// its ray from `origin`, as Scene::Intersect gives it: a sphere's from the lanes' normal,
// the others' by Scene::FillClosest; false if it met nothing. The lane must have
// closest >= 0.
bool FillHitFromLane(const Scene& scene, const RayLanes& lanes, int i, vec3 origin, Hit& hit);

class HitLanes {
 public:
  // The lanes for `scene` (its area light counted if `withAreaLight`) on `target` (Auto:
  // the widest the CPU runs); throws std::invalid_argument naming the targets the CPU
  // runs if it lacks `target`.
  HitLanes(const Scene& scene, bool withAreaLight, SimdTarget target);

  // Lanes [0, count) from their start and (unit) direction: t, closest, closestIndex and
  // closestFace (RayLanes), as for CameraHitLanes. Lanes up to the next multiple of the
  // width are overwritten with lane 0's ray.
  void Trace(RayLanes& lanes, int count) const;
  // Lane i's hit record, as Scene::Intersect gives it for that ray; false if it met
  // nothing. The lane must have closest >= 0.
  bool FillHit(const RayLanes& lanes, int i, Hit& hit) const;

 private:
  const Scene& scene_;
  HitLaneScene k_;
  int width_;
  SecondaryHitKernel kernel_;
};

}  // namespace glint
