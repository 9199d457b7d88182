#include "glint/transport/CameraWallLanes.hpp"

#include <cstddef>

namespace glint {

CameraWallLaneConstants CameraWallConstantsOf(const Wall& room, const Pinhole& camera, int side) {
  CameraWallLaneConstants k{};
  const vec3 eye = camera.Eye();
  k.eye = LaneArray(eye);
  k.viewPlane = LaneArray(camera.ViewPlaneCentre());
  k.pixelWidth = camera.PixelWidth();
  k.pixelHeight = camera.PixelHeight();
  k.halfWidth = camera.HalfWidth();
  k.halfHeight = camera.HalfHeight();
  k.axis = Wall::AxisOf(side);
  const auto a = static_cast<glm::length_t>(k.axis);
  k.gapUp = room.MaxCorner()[a] - eye[a];  // Wall::DistanceThrough's two cases
  k.gapDown = eye[a] - room.Position()[a];
  k.plane = room.PlaneOf(side);
  k.normal = LaneArray(room.Face(side).Normal());
  return k;
}

}  // namespace glint
