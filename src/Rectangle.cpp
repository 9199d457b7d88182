#include "glint/Rectangle.hpp"

namespace glint {

namespace {
// Closed boundaries with this tolerance in (u, v): a ray along a shared edge of two
// faces must hit one of them even when round-off puts it a hair outside both.
constexpr double kEdgeTolerance = 1e-12;
}  // namespace

Rectangle::Rectangle(vec3 corner, vec3 edgeA, vec3 edgeB)
    : corner_(corner),
      edgeA_(edgeA),
      edgeB_(edgeB),
      normal_(glm::normalize(glm::cross(edgeA, edgeB))),
      invA_(edgeA / glm::dot(edgeA, edgeA)),
      invB_(edgeB / glm::dot(edgeB, edgeB)),
      area_(glm::length(glm::cross(edgeA, edgeB))) {}

bool Rectangle::Intersect(vec3 origin, vec3 direction, double tMax, double& t) const {
  const double denom = glm::dot(direction, normal_);
  if (denom == 0.0) return false;  // parallel: a ray in the plane sees no area
  const double tHit = glm::dot(corner_ - origin, normal_) / denom;
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

vec3 Rectangle::PointAt(vec3 origin, vec3 direction, double t) const {
  const vec3 p = origin + t * direction;
  return p - glm::dot(p - corner_, normal_) * normal_;
}

}  // namespace glint
