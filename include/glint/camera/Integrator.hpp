// A light-transport mode: given the root of a ray tree, it traces the ray, grows the
// tree below it and returns the ray's colour (radiance toward the camera).
#pragma once

#include <cstdint>

#include "glint/camera/PixelShaft.hpp"
#include "glint/camera/RayLanes.hpp"
#include "glint/camera/RayTree.hpp"
#include "glint/camera/RenderStats.hpp"
#include "glint/core/Math.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Sampler.hpp"

namespace glint {

class Camera;

class Integrator {
 public:
  Integrator() = default;
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;
  virtual ~Integrator() = default;

  // Traces tree[root] (start, direction, importance set) and fills in its colour and
  // its subtree. Returns the colour. `shaft` is what the pixel that shot the camera ray
  // knows in advance (PixelShaft{} for any other ray: nothing). Its random decisions
  // take their numbers from `sampler`, in the sample the pixel has started.
  virtual Colour Trace(RayTree& tree, std::uint32_t root, const PixelShaft& shaft, Sampler& sampler,
                       RenderStats& stats) const = 0;

  // Lock-step lanes (RayLanes): 0 if the camera rays of a pixel with `shaft` are traced
  // one by one (Trace), else the number traced at once (the SIMD target's width, 1 for
  // its scalar form). TraceLanes then traces lanes [0, count) as Trace would each ray,
  // to the bit.
  virtual int LaneWidth(const PixelShaft& /*shaft*/) const { return 0; }
  // The instruction set of those lanes (resolved: never Auto); the sampler's lanes use it.
  virtual SimdTarget LaneTarget() const { return SimdTarget::Scalar; }
  // Whether each lane's ray takes its first light point (SampleDimension::Light(0)) from
  // the sampler, after its pixel point, as Trace would.
  virtual bool LanesTakeLightPoint() const { return true; }
  virtual void TraceLanes(RayLanes& /*lanes*/, int /*count*/, const PixelShaft& /*shaft*/,
                          RenderStats& /*stats*/) const {}

  // First-hit lanes, for the camera rays of a pixel that LaneWidth leaves to Trace:
  // whether a pass of `rays` rays of a pixel with `shaft` uses them. FindFirstHits finds the first
  // hits of lanes [0, count) from their px, py (RayLanes: direction, t, closest, ...);
  // TraceFromLane traces tree[root], lane `lane`'s camera ray, on from its hit as Trace would, to
  // the bit.
  virtual bool FirstHitLanes(const PixelShaft& /*shaft*/, int /*rays*/) const { return false; }
  virtual void FindFirstHits(RayLanes& /*lanes*/, int /*count*/) const {}
  virtual Colour TraceFromLane(RayTree& tree, std::uint32_t root, const PixelShaft& shaft,
                               const RayLanes& /*lanes*/, int /*lane*/, Sampler& sampler,
                               RenderStats& stats) const {
    return Trace(tree, root, shaft, sampler, stats);
  }
  // A whole group of first-hit lanes at once, up to GroupRays() (a multiple of
  // RayLanes::kMax, at most kMaxGroupRays) rays: tree[firstRoot + i] is ray i's camera ray,
  // for i in [0, count), sample firstSample + i of `sampler`'s pass, lane i % kMax of
  // lanes[i / kMax], its first numbers groups[i / kMax][.][i % kMax]
  // (Sampler::StartSampleWith); writes into colours[i] what TraceFromLane would return
  // for it, to the bit, building each ray's tree (the trees' nodes interleave in the
  // arena), and leaves `sampler` as TraceFromLane would have after the last ray.
  static constexpr int kMaxGroupRays = 64;
  virtual bool TracesGroupsFromLanes() const { return false; }
  virtual int GroupRays() const { return RayLanes::kMax; }
  virtual void TraceGroupFromLanes(RayTree& /*trees*/, std::uint32_t /*firstRoot*/, int /*count*/,
                                   const PixelShaft& /*shaft*/, const RayLanes* /*lanes*/,
                                   Sampler& /*sampler*/, int /*firstSample*/,
                                   const Sampler::FirstGroups* /*groups*/, RenderStats& /*stats*/,
                                   Colour* /*colours*/) const {}

  // The shadow rays it casts, for Camera::PrepareShafts.
  virtual PixelShaft::Lights ShadowLights() const = 0;

  // Light tracing (the Monte Carlo mode's --caustics light): the light paths a pass
  // traces for each camera ray, 0 for none. Camera::RenderChunks has each chunk trace
  // its share, `count` paths numbered by the sampler's samples 0 .. count - 1, which add
  // what they bring to the pixels they are seen in (Camera::Splat).
  virtual int LightPathsPerRay() const { return 0; }
  virtual void TraceLightPaths(Camera& /*camera*/, Sampler& /*sampler*/, int /*count*/,
                               RenderStats& /*stats*/) const {}
};

}  // namespace glint
