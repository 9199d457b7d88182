#include "glint/image/Image.hpp"

namespace glint {

double SrgbEncode(double linear) {
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

std::vector<std::uint8_t> Image::ToDisplay(double exposure) const {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(pixels_.size() * 3);
  for (const Colour& c : pixels_) {
    for (int k = 0; k < 3; ++k) {
      double v = c[k] * exposure;
      v = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
      bytes.push_back(static_cast<std::uint8_t>(std::lround(255.0 * SrgbEncode(v))));
    }
  }
  return bytes;
}

}  // namespace glint
