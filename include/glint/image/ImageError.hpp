// Error of an image against a reference: what the convergence study charts and what the
// regression tests check.
#pragma once

#include "glint/image/Image.hpp"

namespace glint {

struct ImageError {
  double rmse = 0.0;         // over all pixels and channels
  double relativeMse = 0.0;  // mean of (x - r)^2 / (r^2 + 0.01), over pixels and channels
  double blockRmse = 0.0;    // RMSE of the means of block x block tiles (bias shows, noise fades)
  Colour bias{0.0};          // mean of x - r per channel
  // Fireflies: the largest ratio of a pixel's luminance to the reference's mean
  // luminance around it (9x9), where that mean is above 0.01 (about 1 for a converged image).
  double fireflyRatio = 0.0;
};

// Throws std::invalid_argument if the sizes differ.
ImageError CompareImages(const Image& image, const Image& reference, int block = 8);
// Only ImageError::relativeMse, the mean of (x - r)^2 / (r^2 + 0.01); sizes must match.
double RelativeMse(const Image& image, const Image& reference);

}  // namespace glint
