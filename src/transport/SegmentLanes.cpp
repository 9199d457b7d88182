#include "glint/transport/SegmentLanes.hpp"

#include "glint/transport/CameraWallLanes.hpp"  // LaneArray

namespace glint {

SegmentLaneScene SegmentLaneScene::Of(const Scene& scene, bool glassBlocks) {
  SegmentLaneScene k;
  for (const Sphere& s : scene.spheres) {
    if (!glassBlocks && s.GetMaterial().IsTransparent()) continue;
    k.spheres.push_back({LaneArray(s.Centre()), s.Radius() * s.Radius()});
  }
  for (const Cube& c : scene.cubes) {
    if (!glassBlocks && c.GetMaterial().IsTransparent()) continue;
    k.cubes.push_back({LaneArray(c.Centre()), LaneArray(c.Position()), LaneArray(c.MaxCorner()),
                       c.BoundRadius2()});
  }
  return k;
}

}  // namespace glint
