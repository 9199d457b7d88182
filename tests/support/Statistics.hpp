// Statistical tools for testing Monte Carlo code (after nori's tests, written anew):
// a chi-square goodness-of-fit test of a direction sampler against its density, and
// the Sidak correction for many tests in one suite.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "glint/sampling/Rng.hpp"
#include "glint/sampling/Sampling.hpp"

namespace glint::testing {

// Regularised upper incomplete gamma function Q(a, x): the series for x < a + 1, the
// continued fraction (modified Lentz) otherwise.
inline double GammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < 100000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    return 1.0 - sum * std::exp(logPrefix);
  }
  const double tiny = 1e-300;
  double b = x + 1.0 - a;
  double c = 1.0 / tiny;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(logPrefix) * h;
}

// Per-test significance so that `tests` independent tests together reject a correct
// sampler with probability `familyAlpha` (Sidak).
inline double SidakAlpha(double familyAlpha, int tests) {
  return 1.0 - std::pow(1.0 - familyAlpha, 1.0 / tests);
}

// Regularised incomplete beta function I_x(a, b), by its continued fraction (modified
// Lentz), with the symmetry I_x(a, b) = 1 - I_{1-x}(b, a) where the fraction converges
// slowly.
inline double BetaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  double c = 1.0;
  double d = 1.0 - (a + b) * x / (a + 1.0);
  d = 1.0 / (std::abs(d) < kTiny ? kTiny : d);
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const double m2 = 2.0 * m;
    for (const double aa : {m * (b - m) * x / ((a + m2 - 1.0) * (a + m2)),
                            -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0))}) {
      d = 1.0 + aa * d;
      d = 1.0 / (std::abs(d) < kTiny ? kTiny : d);
      c = 1.0 + aa / c;
      c = std::abs(c) < kTiny ? kTiny : c;
      h *= d * c;
    }
    if (std::abs(d * c - 1.0) < 1e-15) break;
  }
  return h;
}

inline double IncompleteBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) +
                                a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * BetaContinuedFraction(a, b, x) / a;
  return 1.0 - front * BetaContinuedFraction(b, a, 1.0 - x) / b;
}

// P(|T| > t) for Student's t with `dof` degrees of freedom: I_{dof/(dof+t^2)}(dof/2, 1/2).
inline double StudentTTwoSided(double t, double dof) {
  return IncompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
}

// The |t| beyond which a two-sided test of level alpha fails, by bisection (P is monotone).
inline double StudentTQuantileTwoSided(double alpha, double dof) {
  double lo = 0.0;
  double hi = 1e3;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (StudentTTwoSided(mid, dof) > alpha ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Welch's t of two means with their standard errors from na and nb values, and the
// Welch-Satterthwaite degrees of freedom.
struct WelchT {
  double t = 0.0;
  double dof = 1.0;
};
inline WelchT Welch(double meanA, double seA, double na, double meanB, double seB, double nb) {
  const double va = seA * seA;
  const double vb = seB * seB;
  WelchT w;
  const double se = std::sqrt(va + vb);
  w.t = se > 0.0 ? (meanA - meanB) / se : (meanA == meanB ? 0.0 : INFINITY);
  const double den = va * va / (na - 1.0) + vb * vb / (nb - 1.0);
  w.dof = den > 0.0 ? (va + vb) * (va + vb) / den : na + nb - 2.0;
  return w;
}

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  double pValue = 0.0;
  std::string failure;  // non-empty if a sample fell where the density is zero
};

// Pools cells with expected count below `minExpected` (smallest first) and returns the
// chi-square statistic and its p-value.
inline ChiSquareResult ChiSquare(const std::vector<double>& observed,
                                 const std::vector<double>& expected, double minExpected = 5.0) {
  ChiSquareResult r;
  std::vector<std::size_t> order(observed.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double poolObs = 0.0;
  double poolExp = 0.0;
  int cells = 0;
  double lastObs = 0.0;
  double lastExp = 0.0;
  for (std::size_t i : order) {
    if (expected[i] <= 0.0 && observed[i] > 0.0) {
      std::ostringstream s;
      s << observed[i] << " samples in cell " << i << " where the density integrates to 0";
      r.failure = s.str();
    }
    poolObs += observed[i];
    poolExp += expected[i];
    if (poolExp < minExpected) continue;
    if (cells > 0) r.statistic += (lastObs - lastExp) * (lastObs - lastExp) / lastExp;
    lastObs = poolObs;
    lastExp = poolExp;
    ++cells;
    poolObs = poolExp = 0.0;
  }
  // A remainder too small to stand alone joins the last cell.
  lastObs += poolObs;
  lastExp += poolExp;
  if (cells > 0) r.statistic += (lastObs - lastExp) * (lastObs - lastExp) / lastExp;
  r.dof = std::max(1, cells - 1);
  r.pValue = GammaQ(0.5 * r.dof, 0.5 * r.statistic);
  return r;
}

// Histogram of sampled directions over (cos theta, phi) cells in the frame of `axis`:
// cos theta in [cosMin, 1] in nCos bands, phi in nPhi sectors, plus one cell for
// everything with cos theta < cosMin. Expected counts integrate the density over each
// cell numerically (sub x sub midpoint rule in (cos theta, phi), where dw = dcos dphi).
struct DirectionalChiSquare {
  vec3 axis;
  double cosMin = -1.0;
  int nCos = 20;
  int nPhi = 40;
  int sub = 16;

  int Cells() const { return nCos * nPhi + 1; }

  int CellOf(const Frame& f, vec3 w) const {
    const vec3 l = f.ToLocal(w);
    if (l.z < cosMin) return nCos * nPhi;
    double phi = std::atan2(l.y, l.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    const int i = std::min(nCos - 1, static_cast<int>((l.z - cosMin) / (1.0 - cosMin) * nCos));
    const int j = std::min(nPhi - 1, static_cast<int>(phi / (2.0 * kPi) * nPhi));
    return i * nPhi + j;
  }

  // Integral of pdf over the band cos in [c0, c1] split into nPhi sectors starting at j.
  double Integrate(const Frame& f, const std::function<double(vec3)>& pdf, double c0, double c1,
                   double phi0, double phi1, int n) const {
    double sum = 0.0;
    const double dc = (c1 - c0) / n;
    const double dphi = (phi1 - phi0) / n;
    for (int a = 0; a < n; ++a) {
      const double c = c0 + (a + 0.5) * dc;
      const double s = SafeSqrt(1.0 - c * c);
      for (int b = 0; b < n; ++b) {
        const double phi = phi0 + (b + 0.5) * dphi;
        sum += pdf(f.ToWorld(vec3(s * std::cos(phi), s * std::sin(phi), c)));
      }
    }
    return sum * dc * dphi;
  }

  ChiSquareResult Run(const std::function<vec3(Pcg32&)>& sample,
                      const std::function<double(vec3)>& pdf, int samples,
                      std::uint64_t seed) const {
    const Frame f = Frame::FromZ(glm::normalize(axis));
    std::vector<double> observed(static_cast<std::size_t>(Cells()), 0.0);
    Pcg32 rng(seed, 7);
    for (int k = 0; k < samples; ++k)
      observed[static_cast<std::size_t>(CellOf(f, sample(rng)))] += 1.0;
    std::vector<double> expected(observed.size(), 0.0);
    const double band = (1.0 - cosMin) / nCos;
    for (int i = 0; i < nCos; ++i) {
      for (int j = 0; j < nPhi; ++j) {
        const double p0 = 2.0 * kPi * j / nPhi;
        const double p1 = 2.0 * kPi * (j + 1) / nPhi;
        expected[static_cast<std::size_t>(i * nPhi + j)] =
            samples * Integrate(f, pdf, cosMin + i * band, cosMin + (i + 1) * band, p0, p1, sub);
      }
    }
    if (cosMin > -1.0) {  // the rest of the sphere, where a lobe may still fall steeply
      double rest = 0.0;
      constexpr int kBands = 2000;
      for (int i = 0; i < kBands; ++i) {
        const double c0 = -1.0 + (cosMin + 1.0) * i / kBands;
        const double c1 = -1.0 + (cosMin + 1.0) * (i + 1) / kBands;
        rest += Integrate(f, pdf, c0, c1, 0.0, 2.0 * kPi, 12);
      }
      expected.back() = samples * rest;
    }
    return ChiSquare(observed, expected);
  }
};

// Mean and standard error of a stream of values.
struct MeanAndError {
  double n = 0.0;
  double mean = 0.0;
  double m2 = 0.0;  // Welford
  void Add(double x) {
    n += 1.0;
    const double d = x - mean;
    mean += d / n;
    m2 += d * (x - mean);
  }
  double StandardError() const { return n > 1.0 ? std::sqrt(m2 / (n - 1.0) / n) : 0.0; }
};

}  // namespace glint::testing
