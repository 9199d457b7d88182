// The Monte Carlo mode's light source: a Lambertian rectangle of radiance Le that emits
// to the side of its normal only (downward, for the ceiling light).
#pragma once

#include "glint/core/Math.hpp"
#include "glint/scene/Rectangle.hpp"

namespace glint {

// A point on the light chosen for a shading point p, as seen from p.
struct LightSample {
  vec3 point;     // y on the light
  vec3 wi;        // unit direction from p to y
  double pdf;     // solid-angle density of wi: |p - y|^2 / (cos(theta_y) A); 0 if unusable
  double invPdf;  // 1 / pdf, computed without waiting for a division; 0 if unusable
  Colour Le;      // radiance leaving y toward p
};

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

  // Next-event estimation: a uniform point on the light, with its density converted from
  // area (1/A) to solid angle at p: p(w) = r^2 / (cos(theta_y) A).
  LightSample SampleLi(vec3 p, double u, double v) const;
  // The same density for a direction from p that hits the light at y.
  double PdfLi(vec3 p, vec3 y) const;
  const Rectangle& Shape() const { return shape_; }
  int Object() const { return object_; }

 private:
  Rectangle shape_;
  Colour radiance_;
  int object_;
};

// Inline: next-event estimation calls it at every wall and Phong hit.
inline LightSample Light::SampleLi(vec3 p, double u, double v) const {
  LightSample s{SamplePoint(u, v), vec3(0.0), 0.0, 0.0, Colour(0.0)};
  const vec3 toLight = s.point - p;
  const double r2 = glm::dot(toLight, toLight);
  if (r2 == 0.0) return s;
  const double invR2 = 1.0 / r2;  // in parallel with the square root
  s.wi = toLight / std::sqrt(r2);
  const double cosLight = -glm::dot(s.wi, shape_.Normal());
  if (cosLight <= 0.0) return s;  // p is behind the emitting side
  s.pdf = r2 / (cosLight * shape_.Area());
  s.invPdf = cosLight * shape_.Area() * invR2;
  s.Le = radiance_;
  return s;
}

}  // namespace glint
