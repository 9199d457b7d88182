// Everything the renderer draws: the room (Wall), the objects (Spheres and Cubes), the
// Monte Carlo area light and the Whitted point lights, and the camera and mode
// settings read from the scene file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glint/scene/Cube.hpp"
#include "glint/scene/Hit.hpp"
#include "glint/scene/Light.hpp"
#include "glint/scene/PointLight.hpp"
#include "glint/scene/Sphere.hpp"
#include "glint/scene/Wall.hpp"

namespace glint {

struct CameraSettings {
  vec3 eye{0.5, 0.5, 2.5};
  // From the eye to the view plane, whose size stays the room's cross-section; 0: the
  // set-up rule's distance, which puts the plane in the room's open front.
  double viewPlaneDistance = 0.0;
  int width = 512;
  int height = 512;
};

struct ModeSettings {
  int spp = 1;            // rays per pixel
  int maxDepth = 10;      // ray iterations (Whitted)
  double exposure = 1.0;  // display mapping: radiance times exposure
};

class Scene {
 public:
  Wall wall;
  std::vector<Sphere> spheres;
  std::vector<Cube> cubes;
  std::optional<Light> light;
  std::vector<PointLight> pointLights;
  CameraSettings camera;
  ModeSettings whitted{4, 10, 1.0};
  ModeSettings mc{64, 10, 1.0};
  std::vector<std::string> objectNames;  // W1..W5, the objects, the lights
  std::vector<std::string> warnings;     // legal but suspicious input, e.g. overlaps

  // Closest hit along the ray. With `withAreaLight`, the light rectangle is part of the
  // scene and wins over the ceiling it lies in (spec: "a ray hits the light").
  bool Intersect(vec3 origin, vec3 direction, Hit& hit, bool withAreaLight) const;
  // The same for a ray known to meet no object and not the light, and to leave the
  // room through wall `side` (PixelShaft): the same hit as Intersect's, found directly.
  void IntersectRoom(vec3 origin, vec3 direction, int side, Hit& hit) const {
    wall.FillHit(origin, direction, wall.DistanceThrough(origin, direction, side), side, hit);
  }
  // Intersect's second half, for SIMD lanes that find the winner themselves
  // (CameraHitLanes): what the ray met first (`index` into spheres or cubes, `face` a
  // wall's side or a cube's face), at distance t, and the hit record made from it.
  enum class Closest : std::int8_t { None, Wall, Sphere, Cube, Light };
  bool FillClosest(Closest winner, int index, int face, double t, vec3 origin, vec3 direction,
                   Hit& hit) const;

  // Whitted shadow ray from p toward q: blocked by opaque objects only, transparent
  // objects let it through (the design's rule). The room is convex, so no wall can
  // stand between two points inside it.
  bool VisibleThroughTransparent(vec3 p, vec3 q) const { return !Blocked(p, q, false); }

  // Monte Carlo shadow ray from p toward a point q on the light: blocked by every
  // object, glass included (light through glass arrives only as a caustic).
  bool Occluded(vec3 p, vec3 q) const { return Blocked(p, q, true); }

  const std::string& ObjectName(int object) const;

 private:
  // Whether an object stands on the open segment from p to q; glass counts if
  // glassBlocks. The segment is tested as it is, p + s (q - p) for s in (0, 1): no
  // normalisation, no square root for the objects it passes by.
  bool Blocked(vec3 p, vec3 q, bool glassBlocks) const;
};

}  // namespace glint
