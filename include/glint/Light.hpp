// The Monte Carlo mode's light source: a Lambertian rectangle of radiance Le that emits
// to the side of its normal only (downward, for the ceiling light).
#pragma once

#include "glint/Math.hpp"
#include "glint/Rectangle.hpp"

namespace glint {

class Light {
 public:
  Light(Rectangle shape, Colour radiance, int object);

  // A uniformly distributed point on the light for the random numbers u, v in [0,1);
  // its density with respect to area is 1 / Area().
  vec3 SamplePoint(double u, double v) const { return shape_.PointFromUV(u, v); }
  double Area() const { return shape_.Area(); }
  vec3 Normal() const { return shape_.Normal(); }
  // Emitted radiance toward direction w (unit, leaving the light).
  Colour Le(vec3 w) const { return glm::dot(w, shape_.Normal()) > 0.0 ? radiance_ : Colour(0.0); }
  Colour Radiance() const { return radiance_; }
  const Rectangle& Shape() const { return shape_; }
  int Object() const { return object_; }

 private:
  Rectangle shape_;
  Colour radiance_;
  int object_;
};

}  // namespace glint
