// A linear-radiance image, row 0 at the top, and the design's mapping function from
// radiance to display values.
#pragma once

#include <cstdint>
#include <vector>

#include "glint/core/Math.hpp"

namespace glint {

class Image {
 public:
  Image() = default;
  Image(int width, int height) : width_(width), height_(height), pixels_(Count(width, height)) {}

  int Width() const { return width_; }
  int Height() const { return height_; }
  Colour& At(int x, int y) { return pixels_[Index(x, y)]; }
  Colour At(int x, int y) const { return pixels_[Index(x, y)]; }
  const std::vector<Colour>& Pixels() const { return pixels_; }
  // Every pixel times `factor`, channel by channel (glint compare's --scale, the tests'
  // power checks).
  Image Scaled(Colour factor) const {
    Image out = *this;
    for (Colour& c : out.pixels_) c *= factor;
    return out;
  }

  // The mean radiance over pixels and channels (0 for an empty image).
  double Mean() const {
    double sum = 0.0;
    for (const Colour& c : pixels_) sum += c.x + c.y + c.z;
    return pixels_.empty() ? 0.0 : sum / (3.0 * static_cast<double>(pixels_.size()));
  }

  // The mapping function: radiance times exposure, clamped to [0,1], the sRGB transfer
  // curve, then 8 bits. Returns RGB bytes, row 0 first.
  std::vector<std::uint8_t> ToDisplay(double exposure) const;

 private:
  static std::size_t Count(int w, int h) {
    return static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  }
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<Colour> pixels_;
};

// The sRGB transfer curve (IEC 61966-2-1) for a linear value in [0, 1].
double SrgbEncode(double linear);

}  // namespace glint
