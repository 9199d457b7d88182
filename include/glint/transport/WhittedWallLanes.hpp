// Lock-step lanes for Whitted mode's commonest ray: a camera ray through a pixel whose
// shaft holds only the room (PixelShaft::roomOnly) ends on a known Lambertian wall, and
// its colour is the wall's local term from the point lights (WhittedIntegrator::
// LocalLight). W rays at a time (RayLanes) run the camera ray, the wall's hit point and
// each point light's term in SIMD lanes (Google Highway, the target chosen at run time,
// `Scalar` the same code at one lane), operation for operation as the scalar code, so
// the bits are the same on every target. The shadow rays the shaft did not answer, and
// the sum over the lights, are the integrator's, per lane.
#pragma once

#include <array>
#include <vector>

#include "glint/camera/Pinhole.hpp"
#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/scene/PointLight.hpp"
#include "glint/scene/Wall.hpp"
#include "glint/transport/CameraWallLanes.hpp"

namespace glint {

// Each point light's part of the local term, lane by lane.
struct PointLightLanes {
  static constexpr int kMaxLights = 4;
  // rho kd / pi * I cos(theta) / r^2 (0 where the light is behind the wall).
  alignas(64) std::array<std::array<RayLanes::Lane, 3>, kMaxLights> term{};
  // 1 where cos(theta) > 0 (the light faces the wall: a shadow ray is cast), 0 elsewhere.
  alignas(64) std::array<RayLanes::Lane, kMaxLights> facing{};
};

struct WhittedWallLaneConstants {
  CameraWallLaneConstants hit;  // the camera ray to the wall
  int lights;
  std::array<std::array<double, 3>, PointLightLanes::kMaxLights> position, intensity;
  std::array<double, 3> diffuse;  // the wall's reflectance times kd / pi (LocalLight's brdf)
};

// One target's kernel: traces rays [0, count) of `lanes` (count a multiple of its width).
using WhittedLaneKernel = void (*)(const WhittedWallLaneConstants& k, RayLanes& lanes, int count,
                                   PointLightLanes& out);

class WhittedWallLanes {
 public:
  // Throws std::invalid_argument if `target` is not one this CPU runs.
  WhittedWallLanes(const Wall& room, const std::vector<PointLight>& lights, const Pinhole& camera,
                   SimdTarget target);

  // The scenes the lanes serve: at most kMaxLights point lights.
  static bool Serves(const std::vector<PointLight>& lights) {
    return lights.size() <= static_cast<std::size_t>(PointLightLanes::kMaxLights);
  }
  SimdTarget Target() const { return target_; }
  int Width() const { return width_; }
  // Rays [0, count) of `lanes`, all ending on wall `side`: their direction and end in
  // `lanes`, each light's term in `out` (count <= RayLanes::kMax; the lanes past count up
  // to a multiple of Width() are traced with lane 0's numbers and ignored).
  void Trace(RayLanes& lanes, int count, int side, PointLightLanes& out) const;

 private:
  std::array<WhittedWallLaneConstants, Wall::kSides> sides_{};
  SimdTarget target_;
  int width_;
  WhittedLaneKernel kernel_;
};

}  // namespace glint
