#include "glint/camera/PixelShaft.hpp"

#include "glint/camera/Camera.hpp"
#include "glint/camera/Shaft.hpp"
#include "glint/scene/Scene.hpp"

namespace glint {

namespace {

// Whether p, a point in the plane of wall `side`, lies inside that face by `margin`.
bool InsideFace(const Wall& room, int side, vec3 p, double margin) {
  const int axis = Wall::AxisOf(side);
  const vec3 lo = room.Position() + vec3(margin);
  const vec3 hi = room.Position() + vec3(room.Size() - margin);
  for (int a = 0; a < 3; ++a) {
    if (a != axis && !(p[a] > lo[a] && p[a] < hi[a])) return false;
  }
  return true;
}

// Whether the shaft misses every object, or every opaque one.
bool MissesObjects(const Shaft& shaft, const Scene& scene, bool glassBlocks, double margin) {
  const auto misses = [&](const auto& object) {
    return (!glassBlocks && object.GetMaterial().IsTransparent()) || shaft.Misses(object, margin);
  };
  return std::all_of(scene.spheres.begin(), scene.spheres.end(), misses) &&
         std::all_of(scene.cubes.begin(), scene.cubes.end(), misses);
}

// The pyramid from a point (the eye, a point light) to a patch of wall.
Shaft Pyramid(vec3 apex, const std::array<vec3, 4>& patch, vec3 patchCentre) {
  Shaft pyramid;
  pyramid.AddPoint(apex);
  pyramid.AddGuide(patchCentre, apex);
  for (const vec3 p : patch) {
    pyramid.AddPoint(p);
    pyramid.AddGuide(p, apex);
  }
  return pyramid;
}

}  // namespace

PixelShaft PixelShaft::Compute(const Scene& scene, const Camera& camera, Lights lights, int x0,
                               int y0, int x1, int y1, PixelShaft known) {
  const Wall& room = scene.wall;
  // Far above round-off (and the 1e-9 |p| origin offsets), far below any feature.
  const double margin = 1e-6 * room.Size();
  const vec3 eye = camera.Eye();
  // The corner rays must all meet one wall face, well inside it; then every ray
  // through the rectangle meets that face inside the quadrilateral of their hits.
  std::array<vec3, 4> patch;
  int side = -1;
  for (std::size_t k = 0; k < 4; ++k) {
    const vec3 d = camera.DirectionThrough((k & 1) != 0 ? x1 : x0, (k & 2) != 0 ? y1 : y0);
    double t = kInfinity;
    int s = -1;
    if (!room.Nearer(eye, d, t, s) || (k > 0 && s != side)) return {};
    side = s;
    patch[k] = eye + t * d;
    if (!InsideFace(room, side, patch[k], margin)) return {};
  }
  const vec3 patchCentre = 0.25 * (patch[0] + patch[1] + patch[2] + patch[3]);

  if (!known.roomOnly) {
    const Shaft view = Pyramid(eye, patch, patchCentre);
    if (!MissesObjects(view, scene, true, margin)) return {};
    if (scene.light && !view.Misses(scene.light->Shape(), margin)) return {};
  }
  PixelShaft result = known;
  result.roomOnly = true;
  result.side = static_cast<std::int8_t>(side);

  if (lights == Lights::Area && scene.light && !known.areaLightVisible) {
    const Rectangle& light = scene.light->Shape();
    const std::array<vec3, 4> lamp = {light.PointFromUV(0.0, 0.0), light.PointFromUV(1.0, 0.0),
                                      light.PointFromUV(0.0, 1.0), light.PointFromUV(1.0, 1.0)};
    Shaft shadow;  // the hull of the patch and the light
    shadow.AddGuide(patchCentre, light.Centre());
    for (std::size_t k = 0; k < 4; ++k) {
      shadow.AddPoint(patch[k]);
      shadow.AddPoint(lamp[k]);
      shadow.AddGuide(patch[k], light.Centre());
      shadow.AddGuide(patchCentre, lamp[k]);
    }
    result.areaLightVisible = MissesObjects(shadow, scene, true, margin);
  }
  if (lights == Lights::Point) {
    for (int i = 0; i < CoveredPointLights(scene); ++i) {
      if (known.PointLightVisible(i)) continue;
      const vec3 light = scene.pointLights[static_cast<std::size_t>(i)].position;
      if (MissesObjects(Pyramid(light, patch, patchCentre), scene, false, margin)) {
        result.pointLightsVisible =
            static_cast<std::uint8_t>(result.pointLightsVisible | (1U << i));
      }
    }
  }
  return result;
}

int PixelShaft::CoveredPointLights(const Scene& scene) {
  return std::min(kMaxPointLights, static_cast<int>(scene.pointLights.size()));
}

bool PixelShaft::Clear(const Scene& scene, Lights lights) const {
  if (!roomOnly) return false;
  if (lights == Lights::Area) return areaLightVisible || !scene.light;
  const unsigned all = (1U << CoveredPointLights(scene)) - 1U;
  return (pointLightsVisible & all) == all;
}

}  // namespace glint
