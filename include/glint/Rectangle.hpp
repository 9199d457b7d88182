// A planar rectangle: corner c and two orthogonal edges a and b. Points are
// c + u a + v b for u, v in [0, 1]; the normal is normalize(a x b). The building block
// of Wall (5), Cube (6) and Light (1).
#pragma once

#include "glint/Math.hpp"

namespace glint {

struct Ray;

class Rectangle {
 public:
  Rectangle() = default;
  Rectangle(vec3 corner, vec3 edgeA, vec3 edgeB);

  // Distance t in (0, tMax) along the ray to the rectangle, from either side.
  // Returns false for a miss or a ray parallel to the plane. Boundaries are closed
  // (with a tolerance of ~1e-12 of an edge), so that a ray along a shared edge of a
  // closed object hits one of its faces instead of slipping between them.
  bool Intersect(vec3 origin, vec3 direction, double tMax, double& t) const;

  // The point at distance t, projected back onto the plane to undo round-off.
  vec3 PointAt(vec3 origin, vec3 direction, double t) const;

  vec3 Corner() const { return corner_; }
  vec3 EdgeA() const { return edgeA_; }
  vec3 EdgeB() const { return edgeB_; }
  vec3 Normal() const { return normal_; }
  double Area() const { return area_; }
  vec3 PointFromUV(double u, double v) const { return corner_ + u * edgeA_ + v * edgeB_; }

 private:
  vec3 corner_{0.0};
  vec3 edgeA_{1.0, 0.0, 0.0};
  vec3 edgeB_{0.0, 1.0, 0.0};
  vec3 normal_{0.0, 0.0, 1.0};
  vec3 invA_{1.0, 0.0, 0.0};  // a / |a|^2: u = dot(p - c, invA)
  vec3 invB_{0.0, 1.0, 0.0};
  double area_ = 1.0;
};

}  // namespace glint
