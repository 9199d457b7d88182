// What a Pixel knows before it shoots: found once per camera by shaft culling
// (Shaft.hpp), it lets the integrators skip tests whose answer is already known.
// The default, knowing nothing, skips nothing.
#pragma once

#include <cstdint>

namespace glint {

class Camera;
class Scene;

struct PixelShaft {
  // Which shadow rays the integrator casts: to the area light, blocked by every object
  // (Monte Carlo), or to the point lights, blocked by opaque objects only (Whitted).
  enum class Lights : std::uint8_t { Area, Point };
  static constexpr int kMaxPointLights = 8;
  // Preparing the shafts of an image costs about what 4-5 rays per pixel save (256x256,
  // one thread: 5.8 ms against 20 ns saved per Monte Carlo path; Whitted breaks even at
  // 4): renders of fewer rays per pixel than this go without.
  static constexpr int kPaysFromRaysPerPixel = 8;

  // Every camera ray through the pixel meets the same wall first: no object and not
  // the area light stand in the pyramid from the eye to the pixel's patch of wall.
  bool roomOnly = false;
  // With roomOnly: the wall (Wall::Side) they all meet, well inside its face.
  std::int8_t side = -1;
  // With roomOnly: no object stands in the hull of that patch and the area light, so
  // next-event estimation from the patch needs no shadow test (the walls block
  // nothing, the room being convex).
  bool areaLightVisible = false;
  // With roomOnly: bit i set if no opaque object stands in the hull of the patch and
  // point light i (i < kMaxPointLights).
  std::uint8_t pointLightsVisible = 0;

  // How many of the scene's point lights the bits cover.
  static int CoveredPointLights(const Scene& scene);
  bool PointLightVisible(int i) const {
    return i < kMaxPointLights && ((pointLightsVisible >> i) & 1U) != 0;
  }

  // The shaft of the camera rays through any point of the image rectangle [x0, x1] x
  // [y0, y1] (pixel (x, y) is [x, x + 1] x [y, y + 1]), with the shadow shafts of
  // `lights`. What holds for a rectangle holds for every pixel inside it, so `known`,
  // the shaft of a rectangle around this one, is taken as it is and not worked out again.
  static PixelShaft Compute(const Scene& scene, const Camera& camera, Lights lights, int x0, int y0,
                            int x1, int y1, PixelShaft known);
  // Whether everything `lights` asks for is known clear: a block's shaft like this is
  // every pixel's in it.
  bool Clear(const Scene& scene, Lights lights) const;
};

}  // namespace glint
