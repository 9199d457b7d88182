// The path from x to y by one reflection off the outside of a mirror sphere (Alhazen's
// problem), and how much the curved mirror spreads a beam along it. With these, next-
// event estimation sees the light in a mirror sphere (MirroredLight.hpp).
#pragma once

#include <optional>

#include "glint/core/Math.hpp"

namespace glint {

struct SphereReflection {
  vec3 point;       // m on the sphere: the normal there bisects the directions to x and y
  vec3 normal;      // outward unit normal at m
  double toX;       // d1 = |x - m|
  double toY;       // d2 = |y - m|
  double cosTheta;  // cosine of the angle of incidence (= of reflection), in (0, 1]
  // dA_perp(y) / d omega(x): the area, perpendicular to the reflected ray at y, that a
  // unit solid angle of directions leaving x covers after the reflection. A plane
  // mirror gives (d1 + d2)^2; a convex sphere of radius R spreads the beam further, by
  // its two focal lengths (Coddington's equations for a mirror: tangential R cos/2,
  // sagittal R / (2 cos)):
  //   (d1 + d2 + 2 d1 d2 / (R cos)) (d1 + d2 + 2 d1 d2 cos / R).
  // The generalised geometry term of the path is cos(theta_x) cos(theta_y) / spread.
  double spread;
};

// The reflection point on the sphere (centre c, radius R) of the path x -> m -> y, where
// x and y both see m (they lie above its tangent plane), or nothing if there is none:
// x or y inside the sphere, or the sphere between them. There is at most one such point
// (the sphere is convex). It lies in the plane of c, x and y, at the angle phi from
// x's direction where the angles of incidence from x and from y are equal:
//   p sin(phi) / |x - m| = q sin(beta - phi) / |y - m|
// (p = |x - c|, q = |y - c|, beta the angle between x - c and y - c), solved by Newton's
// method kept inside a bracket where both see m.
std::optional<SphereReflection> ReflectOffSphere(vec3 centre, double radius, vec3 x, vec3 y);

}  // namespace glint
