// Do two independent renders A and B estimate the same image as a reference? The bias
// test behind `glint compare`: the noise of a block's mean comes from the renders
// themselves, the spread of A - B (and of R1 - R2 for a noisy reference given twice).
#pragma once

#include "glint/image/Image.hpp"

namespace glint {

struct BiasTestOptions {
  int block = 16;             // blocks of block x block pixels, each channel a test
  double meanSigma = 4.0;     // the whole image's mean may differ by this many standard errors
  double familyAlpha = 1e-3;  // the chance that any block of an unbiased pair fails (Sidak)
};

struct BiasVerdict {
  double meanRatio = 1.0;   // mean of (A + B) / 2 over the reference's mean
  double meanZ = 0.0;       // that difference in standard errors
  int blockTests = 0;       // blocks times channels
  double maxBlockZ = 0.0;   // the largest |z| of a block and channel
  int beyond4 = 0;          // block tests with |z| > 4
  double blockLimit = 0.0;  // |z| above this fails a block (Sidak-corrected familyAlpha)
  int failedBlocks = 0;     // block tests beyond blockLimit
  bool agree = true;
};

// The block and whole-image means of E = (A + B) / 2 against R (the mean of ref and ref2,
// or ref alone, taken as exact, when ref2 is null). For a block of n pixels,
//   Var(mean E) = sum_i Var(A_i) / (2 n^2) ~ sum_i (A_i - B_i)^2 / (4 n^2),
// unbiased since E[(A_i - B_i)^2] = 2 Var(A_i) for independent A and B; the same holds
// for R. z = (mean E - mean R) / sqrt(Var(mean E) + Var(mean R)). A block whose spread is
// zero (say, black in all four images) passes when its means agree exactly.
// Throws std::invalid_argument if the sizes differ.
BiasVerdict TestBias(const Image& a, const Image& b, const Image& ref, const Image* ref2,
                     BiasTestOptions options = {});

// |z| beyond which a two-sided normal test of level alpha fails (inverse of erfc).
double NormalQuantileTwoSided(double alpha);

}  // namespace glint
