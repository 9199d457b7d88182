#include "glint/Scene.hpp"

namespace glint {

bool Scene::Intersect(vec3 origin, vec3 direction, Hit& hit, bool withAreaLight) const {
  hit = Hit{};
  bool found = wall.Intersect(origin, direction, kInfinity, hit);
  for (const Sphere& s : spheres) found |= s.Intersect(origin, direction, hit.t, hit);
  for (const Cube& c : cubes) found |= c.Intersect(origin, direction, hit.t, hit);
  if (withAreaLight && light) {
    // The light is coplanar with the ceiling: on a tie (equal t up to round-off) the
    // light wins, so the allowance scales with t.
    const double tMax = found ? hit.t * (1.0 + 1e-12) + 1e-15 : kInfinity;
    double t = 0.0;
    if (light->Shape().Intersect(origin, direction, tMax, t)) {
      hit.t = t;
      hit.point = light->Shape().PointAt(origin, direction, t);
      hit.normal = light->Normal();
      hit.material = nullptr;
      hit.object = light->Object();
      hit.light = true;
      found = true;
    }
  }
  return found;
}

bool Scene::Blocked(vec3 p, vec3 q, bool glassBlocks) const {
  const vec3 toQ = q - p;
  const double distance = glm::length(toQ);
  if (distance == 0.0) return false;  // never normalise a zero-length vector
  const vec3 d = toQ / distance;
  for (const Sphere& s : spheres) {
    if ((glassBlocks || !s.GetMaterial().IsTransparent()) && s.IntersectAny(p, d, distance)) {
      return true;
    }
  }
  for (const Cube& c : cubes) {
    if ((glassBlocks || !c.GetMaterial().IsTransparent()) && c.IntersectAny(p, d, distance)) {
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
