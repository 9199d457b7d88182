#include "glint/scene/Rectangle.hpp"

namespace glint {

Rectangle::Rectangle(vec3 corner, vec3 edgeA, vec3 edgeB)
    : corner_(corner),
      edgeA_(edgeA),
      edgeB_(edgeB),
      normal_(glm::normalize(glm::cross(edgeA, edgeB))),
      invA_(edgeA / glm::dot(edgeA, edgeA)),
      invB_(edgeB / glm::dot(edgeB, edgeB)),
      area_(glm::length(glm::cross(edgeA, edgeB))) {}

vec3 Rectangle::PointAt(vec3 origin, vec3 direction, double t) const {
  const vec3 p = origin + t * direction;
  return p - glm::dot(p - corner_, normal_) * normal_;
}

}  // namespace glint
