// Lock-step lanes for the Monte Carlo mode's commonest path: a camera ray through a
// pixel whose shaft holds only the room (PixelShaft::roomOnly) ends on a known terminal
// wall, and its colour is that wall's next-event estimate from one light point. W rays
// at a time (RayLanes) run camera ray generation, the wall's distance and hit point and
// the estimate in SIMD lanes (Google Highway, the target chosen at run time, `Scalar`
// the same code at one lane). Each lane does, operation for operation and in the same
// order, what MonteCarloIntegrator::Trace does for one such ray (Pinhole::DirectionThrough,
// Wall::DistanceThrough and FillHit, DirectLightLambertian), so the bits are the same on
// every target; the shadow test the shaft did not answer is the integrator's, per lane.
#pragma once

#include <array>

#include "glint/camera/Pinhole.hpp"
#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/scene/Light.hpp"
#include "glint/scene/Wall.hpp"
#include "glint/transport/CameraWallLanes.hpp"

namespace glint {

// What the lanes need of the scene for rays that end on one wall side: constants only.
struct WallLaneConstants {
  CameraWallLaneConstants hit;  // the camera ray to the wall
  std::array<double, 3> lightCorner, lightEdgeA, lightEdgeB, lightNormal;
  double lightArea;
  std::array<double, 3> radiance;  // the light's Le times the wall's reflectance
};

// One target's kernel: traces rays [0, count) of `lanes` (count a multiple of its width).
using WallLaneKernel = void (*)(const WallLaneConstants& k, RayLanes& lanes, int count);

class TerminalWallLanes {
 public:
  // Throws std::invalid_argument if `target` is not one this CPU runs.
  TerminalWallLanes(const Wall& room, const Light& light, const Pinhole& camera, SimdTarget target);

  SimdTarget Target() const { return target_; }
  int Width() const { return width_; }
  // Rays [0, count) of `lanes`, all ending on wall `side` (count <= RayLanes::kMax; the
  // lanes past count up to a multiple of Width() are traced with lane 0's numbers and
  // ignored).
  void Trace(RayLanes& lanes, int count, int side) const;

 private:
  std::array<WallLaneConstants, Wall::kSides> sides_{};
  SimdTarget target_;
  int width_;
  WallLaneKernel kernel_;
};

}  // namespace glint
