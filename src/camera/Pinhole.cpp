#include "glint/camera/Pinhole.hpp"

#include <cmath>

namespace glint {

Pinhole::Pinhole(vec3 eye, vec3 viewDirection, double distance, double halfWidth, double halfHeight,
                 int width, int height)
    : eye_(eye),
      viewDirection_(viewDirection),
      planeCentre_(eye + distance * viewDirection),
      distance_(distance),
      halfWidth_(halfWidth),
      halfHeight_(halfHeight),
      pixelWidth_(2.0 * halfWidth / static_cast<double>(width)),
      pixelHeight_(2.0 * halfHeight / static_cast<double>(height)),
      inversePixelArea_(1.0 / (pixelWidth_ * pixelHeight_)),
      width_(width),
      height_(height) {}

PinholeImportance Pinhole::Importance(vec3 x, vec3 n) const {
  const vec3 w = x - eye_;
  const double along = glm::dot(w, viewDirection_);  // r cos(theta)
  if (!(along > 0.0)) return {};
  const vec3 q = eye_ + (distance_ / along) * w;  // where the ray from the eye meets the plane
  const double px = (q.x - planeCentre_.x + halfWidth_) / pixelWidth_;
  const double py = (halfHeight_ - (q.y - planeCentre_.y)) / pixelHeight_;
  if (!(px >= 0.0 && px < width_ && py >= 0.0 && py < height_)) return {};
  const double r2 = glm::dot(w, w);
  const double r = std::sqrt(r2);
  const double cosTheta = along / r;
  const double cosX = std::abs(glm::dot(n, w)) / r;
  PinholeImportance out;
  out.we = distance_ * distance_ * inversePixelArea_ * cosX / (cosTheta * cosTheta * cosTheta * r2);
  out.pixel = static_cast<std::size_t>(static_cast<int>(py)) * static_cast<std::size_t>(width_) +
              static_cast<std::size_t>(static_cast<int>(px));
  return out;
}

}  // namespace glint
