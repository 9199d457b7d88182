#include "glint/image/BiasTest.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

// Sums over a rectangle of pixels for one channel k (or all three averaged, k = 3).
struct Sums {
  double e = 0.0;     // sum of (A + B) / 2
  double r = 0.0;     // sum of the reference
  double varE = 0.0;  // sum of (A - B)^2 / 4
  double varR = 0.0;  // sum of (R1 - R2)^2 / 4
  double n = 0.0;
};

double Channel(Colour c, int k) {
  return k < 3 ? c[k] : (c.x + c.y + c.z) / 3.0;
}

Sums Sum(const Image& a, const Image& b, const Image& ref, const Image* ref2, int x0, int y0,
         int x1, int y1, int k) {
  Sums s;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const double va = Channel(a.At(x, y), k);
      const double vb = Channel(b.At(x, y), k);
      const double r1 = Channel(ref.At(x, y), k);
      const double r2 = ref2 ? Channel(ref2->At(x, y), k) : r1;
      s.e += 0.5 * (va + vb);
      s.r += 0.5 * (r1 + r2);
      s.varE += 0.25 * (va - vb) * (va - vb);
      s.varR += 0.25 * (r1 - r2) * (r1 - r2);
      s.n += 1.0;
    }
  }
  return s;
}

// z of the difference of means; 0 for identical means, infinite for a difference with no
// spread to excuse it.
double Z(const Sums& s) {
  const double difference = (s.e - s.r) / s.n;
  const double se = std::sqrt(s.varE + s.varR) / s.n;
  if (se > 0.0) return difference / se;
  return difference == 0.0 ? 0.0 : std::copysign(INFINITY, difference);
}

}  // namespace

double NormalQuantileTwoSided(double alpha) {
  // Solve erfc(z / sqrt 2) = alpha by bisection: erfc is monotone, 60 halvings suffice.
  double lo = 0.0;
  double hi = 40.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

BiasVerdict TestBias(const Image& a, const Image& b, const Image& ref, const Image* ref2,
                     BiasTestOptions options) {
  const auto same = [&](const Image& i) {
    return i.Width() == ref.Width() && i.Height() == ref.Height();
  };
  if (!same(a) || !same(b) || (ref2 && !same(*ref2))) {
    throw std::invalid_argument("the images differ in size");
  }
  BiasVerdict v;
  const int w = ref.Width();
  const int h = ref.Height();
  const Sums whole = Sum(a, b, ref, ref2, 0, 0, w, h, 3);
  v.meanRatio = whole.r != 0.0 ? whole.e / whole.r : (whole.e == 0.0 ? 1.0 : INFINITY);
  v.meanZ = Z(whole);
  const int bs = options.block;
  const int nx = (w + bs - 1) / bs;
  const int ny = (h + bs - 1) / bs;
  v.blockTests = nx * ny * 3;
  // Sidak: each of m tests at 1 - (1 - alpha)^(1/m) keeps the family's level at alpha.
  const double perTest = -std::expm1(std::log1p(-options.familyAlpha) / v.blockTests);
  v.blockLimit = NormalQuantileTwoSided(perTest);
  for (int by = 0; by < ny; ++by) {
    for (int bx = 0; bx < nx; ++bx) {
      for (int k = 0; k < 3; ++k) {
        const double z =
            std::abs(Z(Sum(a, b, ref, ref2, bx * bs, by * bs, std::min(w, (bx + 1) * bs),
                           std::min(h, (by + 1) * bs), k)));
        v.maxBlockZ = std::max(v.maxBlockZ, z);
        v.beyond4 += z > 4.0 ? 1 : 0;
        v.failedBlocks += z > v.blockLimit ? 1 : 0;
      }
    }
  }
  v.agree = std::abs(v.meanZ) <= options.meanSigma && v.failedBlocks == 0;
  return v;
}

}  // namespace glint
