#include "glint/image/ImageError.hpp"

#include <stdexcept>
#include <string>

namespace glint {

namespace {

// The largest ratio of a pixel's luminance to the mean luminance of the reference in
// the 9x9 neighbourhood around it, among pixels whose neighbourhood is not dark.
double FireflyRatio(const Image& image, const Image& reference) {
  double worst = 0.0;
  for (int y = 0; y < image.Height(); ++y) {
    for (int x = 0; x < image.Width(); ++x) {
      double sum = 0.0;
      int n = 0;
      for (int v = std::max(0, y - 4); v <= std::min(image.Height() - 1, y + 4); ++v) {
        for (int u = std::max(0, x - 4); u <= std::min(image.Width() - 1, x + 4); ++u) {
          sum += Luminance(reference.At(u, v));
          ++n;
        }
      }
      const double mean = sum / n;
      if (mean > 0.01) worst = std::max(worst, Luminance(image.At(x, y)) / mean);
    }
  }
  return worst;
}

}  // namespace

ImageError CompareImages(const Image& image, const Image& reference, int block) {
  if (image.Width() != reference.Width() || image.Height() != reference.Height()) {
    throw std::invalid_argument("the reference is " + std::to_string(reference.Width()) + "x" +
                                std::to_string(reference.Height()) + ", the image " +
                                std::to_string(image.Width()) + "x" +
                                std::to_string(image.Height()));
  }
  ImageError e;
  const double count = 3.0 * image.Width() * image.Height();
  for (int y = 0; y < image.Height(); ++y) {
    for (int x = 0; x < image.Width(); ++x) {
      const Colour d = image.At(x, y) - reference.At(x, y);
      e.rmse += glm::dot(d, d);
      e.bias += d;
    }
  }
  e.rmse = std::sqrt(e.rmse / count);
  e.relativeMse = RelativeMse(image, reference);
  e.bias /= count / 3.0;
  const int nx = image.Width() / block;
  const int ny = image.Height() / block;
  double blockSum = 0.0;
  for (int by = 0; by < ny; ++by) {
    for (int bx = 0; bx < nx; ++bx) {
      Colour d(0.0);
      for (int y = by * block; y < (by + 1) * block; ++y) {
        for (int x = bx * block; x < (bx + 1) * block; ++x) {
          d += image.At(x, y) - reference.At(x, y);
        }
      }
      d /= static_cast<double>(block * block);
      blockSum += glm::dot(d, d);
    }
  }
  e.blockRmse = nx * ny > 0 ? std::sqrt(blockSum / (3.0 * nx * ny)) : 0.0;
  e.fireflyRatio = FireflyRatio(image, reference);
  return e;
}

double RelativeMse(const Image& image, const Image& reference) {
  double sum = 0.0;
  for (int y = 0; y < image.Height(); ++y) {
    for (int x = 0; x < image.Width(); ++x) {
      const Colour d = image.At(x, y) - reference.At(x, y);
      const Colour r = reference.At(x, y);
      sum += glm::dot(d * d, Colour(1.0) / (r * r + Colour(0.01)));
    }
  }
  return sum / (3.0 * image.Width() * image.Height());
}

}  // namespace glint
