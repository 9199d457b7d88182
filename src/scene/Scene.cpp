#include "glint/scene/Scene.hpp"

namespace glint {

bool Scene::Intersect(vec3 origin, vec3 direction, Hit& hit, bool withAreaLight) const {
  // Distances first, the hit record once for the winner: most candidates lose.
  Closest winner = Closest::None;
  double t = kInfinity;
  int index = 0;
  int face = 0;
  if (wall.Nearer(origin, direction, t, face)) winner = Closest::Wall;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    if (spheres[i].Nearer(origin, direction, t)) {
      winner = Closest::Sphere;
      index = static_cast<int>(i);
    }
  }
  for (std::size_t i = 0; i < cubes.size(); ++i) {
    if (cubes[i].Nearer(origin, direction, t, face)) {
      winner = Closest::Cube;
      index = static_cast<int>(i);
    }
  }
  if (withAreaLight && light) {
    // The light is coplanar with the ceiling: on a tie (equal t up to round-off) the
    // light wins, so the allowance scales with t.
    const double tMax = winner != Closest::None ? t * (1.0 + 1e-12) + 1e-15 : kInfinity;
    if (light->Shape().Intersect(origin, direction, tMax, t)) winner = Closest::Light;
  }
  return FillClosest(winner, index, face, t, origin, direction, hit);
}

bool Scene::FillClosest(Closest winner, int index, int face, double t, vec3 origin, vec3 direction,
                        Hit& hit) const {
  switch (winner) {
    case Closest::None:
      hit = Hit{};
      return false;
    case Closest::Wall:
      wall.FillHit(origin, direction, t, face, hit);
      break;
    case Closest::Sphere:
      spheres[static_cast<std::size_t>(index)].FillHit(origin, direction, t, hit);
      break;
    case Closest::Cube:
      cubes[static_cast<std::size_t>(index)].FillHit(origin, direction, t, face, hit);
      break;
    case Closest::Light:
      hit.t = t;
      hit.point = light->Shape().PointAt(origin, direction, t);
      hit.normal = light->Normal();
      hit.material = nullptr;
      hit.object = light->Object();
      hit.light = true;
      break;
  }
  return true;
}

bool Scene::Blocked(vec3 p, vec3 q, bool glassBlocks) const {
  const vec3 v = q - p;
  for (const Sphere& s : spheres) {
    if ((glassBlocks || !s.GetMaterial().IsTransparent()) && s.IntersectsSegment(p, v)) {
      return true;
    }
  }
  for (const Cube& c : cubes) {
    if ((glassBlocks || !c.GetMaterial().IsTransparent()) && c.IntersectsSegment(p, v)) {
      return true;
    }
  }
  return false;  // the room is convex: no wall stands between two points inside it
}

const std::string& Scene::ObjectName(int object) const {
  static const std::string kNone = "none";
  if (object < 0 || object >= static_cast<int>(objectNames.size())) return kNone;
  return objectNames[object];
}

}  // namespace glint
