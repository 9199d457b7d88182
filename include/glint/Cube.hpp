// An axis-aligned cube of six Rectangles from Position (its minimum corner) and Size,
// with outward normals: O3 of the canonical scene. It may be opaque or transparent.
#pragma once

#include <array>

#include "glint/Hit.hpp"
#include "glint/Material.hpp"
#include "glint/Rectangle.hpp"

namespace glint {

class Cube {
 public:
  Cube(vec3 position, double size, const Material& material, int object);

  bool Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const;
  bool IntersectAny(vec3 origin, vec3 direction, double tMax) const;

  vec3 Position() const { return position_; }
  double Size() const { return size_; }
  const Material& GetMaterial() const { return material_; }
  int Object() const { return object_; }
  const std::array<Rectangle, 6>& Faces() const { return faces_; }

 private:
  vec3 position_;
  double size_;
  Material material_;
  int object_;
  std::array<Rectangle, 6> faces_;
};

}  // namespace glint
