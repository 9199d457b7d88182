// The sine and cosine of an angle given in turns (the 2 pi u of a sampled azimuth),
// written out instead of taken from libm: the same multiply-adds in the scalar code and
// in every SIMD lane (issue #27: lanes stay bit-identical to one lane only if libm is
// not in them), and faster than libm's sincos, which held 12% of a render with diffuse
// walls (BENCHMARKS.md, "SIMD lanes").
#pragma once

namespace glint {

struct SinCos {
  double sin;
  double cos;
};

// sin(2 pi u) and cos(2 pi u) for |u| < 2^49, within 2.5e-16 of the exact values (the
// test checks against long double), exact at whole quarter turns: (0, 1), (1, 0), ...
// (libm's sin(2 pi * 0.5) is 1.2e-16, the rounding of pi).
inline SinCos SinCosTurns(double u) {
  // Quarter turns: 4u is exact, its nearest whole q too (adding and taking away 1.5 2^52
  // rounds to it), and so is f = 4u - q, in [-1/2, 1/2] (its bits are among 4u's).
  constexpr double kRound = 0x1.8p52;
  const double e = 4.0 * u;
  const double q = (e + kRound) - kRound;
  const double f = e - q;
  const double x = f * 1.57079632679489661923;  // pi/2 f, in [-pi/4, pi/4]
  const double x2 = x * x;
  const double x4 = x2 * x2;
  const double x8 = x4 * x4;
  // Taylor series, by Estrin's scheme (a chain of 5 products where Horner's has 9: 17.7
  // against 24.9 ns a call in a dependent loop; libm 30.3): the first term left out,
  // |x|^19 / 19! and |x|^18 / 18!, is below 1e-19 at |x| = pi/4.
  const double s =
      x + x * x2 *
              (((-1.0 / 6.0 + x2 * (1.0 / 120.0)) + x4 * (-1.0 / 5040.0 + x2 * (1.0 / 362880.0))) +
               x8 * ((-1.0 / 39916800.0 + x2 * (1.0 / 6227020800.0)) +
                     x4 * (-1.0 / 1307674368000.0 + x2 * (1.0 / 355687428096000.0))));
  const double c =
      1.0 + x2 * (((-1.0 / 2.0 + x2 * (1.0 / 24.0)) + x4 * (-1.0 / 720.0 + x2 * (1.0 / 40320.0))) +
                  x8 * ((-1.0 / 3628800.0 + x2 * (1.0 / 479001600.0)) +
                        x4 * (-1.0 / 87178291200.0 + x2 * (1.0 / 20922789888000.0))));
  // 2 pi u = x + q pi/2: quarter turn q mod 4 turns (sin x, cos x) into (cos x, -sin x),
  // (-sin x, -cos x) or (-cos x, sin x).
  const auto quarter = static_cast<unsigned>(static_cast<long long>(q) & 3);
  const double sine = (quarter & 1U) != 0 ? c : s;
  const double cosine = (quarter & 1U) != 0 ? s : c;
  return {(quarter & 2U) != 0 ? -sine : sine, ((quarter + 1U) & 2U) != 0 ? -cosine : cosine};
}

}  // namespace glint
