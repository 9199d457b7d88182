// A planar rectangle: corner c and two orthogonal edges a and b. Points are
// c + u a + v b for u, v in [0, 1]; the normal is normalize(a x b). The building block
// of Wall (5), Cube (6) and Light (1).
#pragma once

#include "glint/core/Math.hpp"

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
  // a / |a|^2 and b / |b|^2: a point's (u, v) are dot(p - corner, InvA()), ... .
  vec3 InvA() const { return invA_; }
  vec3 InvB() const { return invB_; }
  double Area() const { return area_; }
  vec3 PointFromUV(double u, double v) const { return corner_ + u * edgeA_ + v * edgeB_; }
  vec3 Centre() const { return PointFromUV(0.5, 0.5); }
  // Support function h(n) = max over the rectangle of n.x: the best corner (shaft culling).
  double Support(vec3 n) const {
    return glm::dot(n, corner_) + std::max(0.0, glm::dot(n, edgeA_)) +
           std::max(0.0, glm::dot(n, edgeB_));
  }

 private:
  vec3 corner_{0.0};
  vec3 edgeA_{1.0, 0.0, 0.0};
  vec3 edgeB_{0.0, 1.0, 0.0};
  vec3 normal_{0.0, 0.0, 1.0};
  vec3 invA_{1.0, 0.0, 0.0};  // a / |a|^2: u = dot(p - c, invA)
  vec3 invB_{0.0, 1.0, 0.0};
  double area_ = 1.0;
};

inline bool Rectangle::Intersect(vec3 origin, vec3 direction, double tMax, double& t) const {
  // Closed boundaries with this tolerance in (u, v): a ray along a shared edge of two
  // faces must hit one of them even when round-off puts it a hair outside both.
  constexpr double kEdgeTolerance = 1e-12;
  const double denom = glm::dot(direction, normal_);
  if (denom == 0.0) return false;  // parallel: a ray in the plane sees no area
  const double distance = glm::dot(corner_ - origin, normal_);
  // t = distance / denom > 0 needs equal signs: most rays that go away from the plane
  // are turned back before the division.
  if ((distance > 0.0) != (denom > 0.0)) return false;
  const double tHit = distance / denom;
  if (!(tHit > 0.0 && tHit < tMax)) return false;
  const vec3 q = origin + tHit * direction - corner_;
  const double u = glm::dot(q, invA_);
  const double v = glm::dot(q, invB_);
  if (u < -kEdgeTolerance || u > 1.0 + kEdgeTolerance || v < -kEdgeTolerance ||
      v > 1.0 + kEdgeTolerance) {
    return false;
  }
  t = tHit;
  return true;
}

}  // namespace glint
