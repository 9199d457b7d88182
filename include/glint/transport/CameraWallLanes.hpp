// What SIMD lanes need to follow a camera ray to the wall a roomOnly pixel sees
// (PixelShaft::roomOnly): the pinhole's constants and one wall side's. Both modes' wall
// lanes (TerminalWallLanes, WhittedWallLanes) start from it; the per-target code that
// uses it is CameraWallLanes-inl.h beside it.
#pragma once

#include <array>

#include "glint/camera/Pinhole.hpp"
#include "glint/scene/Wall.hpp"

namespace glint {

struct CameraWallLaneConstants {
  std::array<double, 3> eye, viewPlane;  // the view plane's point at (0, 0) offset: its centre
  double pixelWidth, pixelHeight, halfWidth, halfHeight;
  int axis;               // the wall's axis (Wall::AxisOf)
  double gapUp, gapDown;  // the eye's distance to the wall's plane for d[axis] > 0, <= 0
  double plane;           // the wall's plane coordinate
  std::array<double, 3> normal;
};

CameraWallLaneConstants CameraWallConstantsOf(const Wall& room, const Pinhole& camera, int side);

inline std::array<double, 3> LaneArray(vec3 v) {
  return {v.x, v.y, v.z};
}

}  // namespace glint
