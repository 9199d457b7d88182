// The room: five Rectangles W1..W5 (left, ceiling, right, floor, back) of the cube
// [Position, Position + Size]^3, with normals into the room. The front is open.
#pragma once

#include <array>

#include "glint/Hit.hpp"
#include "glint/Material.hpp"
#include "glint/Rectangle.hpp"

namespace glint {

class Wall {
 public:
  enum Side { kLeft = 0, kCeiling, kRight, kFloor, kBack, kSides };

  Wall() : Wall(vec3(0.0), 1.0, {}) {}
  // materials[i] and object ids first + i belong to side i.
  Wall(vec3 position, double size, const std::array<Material, kSides>& materials,
       int firstObject = 0);

  bool Intersect(vec3 origin, vec3 direction, double tMax, Hit& hit) const;

  vec3 Position() const { return position_; }
  double Size() const { return size_; }
  vec3 Centre() const { return position_ + vec3(0.5 * size_); }
  const Rectangle& Face(int side) const { return faces_[side]; }
  const Material& GetMaterial(int side) const { return materials_[side]; }
  // True if p lies inside the room (closed box).
  bool Contains(vec3 p, double tolerance = 0.0) const;

 private:
  vec3 position_;
  double size_;
  std::array<Material, kSides> materials_;
  std::array<Rectangle, kSides> faces_;
  int firstObject_;
};

}  // namespace glint
