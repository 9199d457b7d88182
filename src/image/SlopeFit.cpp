#include "glint/image/SlopeFit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace glint {

namespace {

struct Line {
  double slope = std::numeric_limits<double>::quiet_NaN();
  double logX = 0.0;
  double logY = 0.0;
  int points = 0;
};

Line LeastSquares(const std::vector<double>& lx, const std::vector<double>& ly) {
  Line line;
  line.points = static_cast<int>(lx.size());
  if (lx.size() < 2) return line;
  const double n = static_cast<double>(lx.size());
  line.logX = std::accumulate(lx.begin(), lx.end(), 0.0) / n;
  line.logY = std::accumulate(ly.begin(), ly.end(), 0.0) / n;
  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < lx.size(); ++i) {
    sxx += (lx[i] - line.logX) * (lx[i] - line.logX);
    sxy += (lx[i] - line.logX) * (ly[i] - line.logY);
  }
  if (sxx > 0.0) line.slope = sxy / sxx;
  return line;
}

// The rungs' points (median x, mean y) in logs, those with x, y > 0.
Line FitPoints(const std::vector<Rung>& rungs) {
  std::vector<double> lx;
  std::vector<double> ly;
  for (const Rung& r : rungs) {
    if (r.x.empty()) continue;
    const double x = MedianOf(r.x);
    const double y = MeanOf(r.y);
    if (x > 0.0 && y > 0.0 && std::isfinite(x) && std::isfinite(y)) {
      lx.push_back(std::log(x));
      ly.push_back(std::log(y));
    }
  }
  return LeastSquares(lx, ly);
}

}  // namespace

double MedianOf(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

double MeanOf(const std::vector<double>& values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

namespace {

// The resampling units of a rung: one per block, or one per repeat; each a list of repeats.
std::vector<std::vector<std::size_t>> Units(const Rung& r) {
  std::vector<std::vector<std::size_t>> units;
  std::vector<int> ids;
  for (std::size_t j = 0; j < r.x.size(); ++j) {
    if (r.block.empty()) {
      units.push_back({j});
      continue;
    }
    const auto at = std::find(ids.begin(), ids.end(), r.block[j]);
    if (at == ids.end()) {
      ids.push_back(r.block[j]);
      units.push_back({j});
    } else {
      units[static_cast<std::size_t>(at - ids.begin())].push_back(j);
    }
  }
  return units;
}

}  // namespace

Slope FitSlope(const std::vector<Rung>& rungs, Pcg32& rng, int resamples) {
  const Line line = FitPoints(rungs);
  Slope s{line.slope, 0.0, line.logX, line.logY, line.points};
  std::vector<std::vector<std::vector<std::size_t>>> units;
  units.reserve(rungs.size());
  for (const Rung& r : rungs) units.push_back(Units(r));
  const bool repeated =
      std::all_of(units.begin(), units.end(), [](const auto& u) { return u.size() >= 2; });
  if (!std::isfinite(line.slope) || !repeated) return s;
  // The bootstrap: each rung's units drawn with replacement (x and y of a repeat together).
  std::vector<Rung> drawn(rungs.size());
  double sum = 0.0;
  double sum2 = 0.0;
  int count = 0;
  for (int b = 0; b < resamples; ++b) {
    for (std::size_t k = 0; k < rungs.size(); ++k) {
      const std::size_t n = units[k].size();
      drawn[k].x.clear();
      drawn[k].y.clear();
      for (std::size_t u = 0; u < n; ++u) {
        const auto pick =
            std::min(n - 1, static_cast<std::size_t>(rng.Uniform() * static_cast<double>(n)));
        for (const std::size_t j : units[k][pick]) {
          drawn[k].x.push_back(rungs[k].x[j]);
          drawn[k].y.push_back(rungs[k].y[j]);
        }
      }
    }
    const double v = FitPoints(drawn).slope;
    if (!std::isfinite(v)) continue;
    sum += v;
    sum2 += v * v;
    ++count;
  }
  if (count >= 2) {
    const double mean = sum / count;
    s.standardError = std::sqrt(std::max(0.0, (sum2 - count * mean * mean) / (count - 1)));
  }
  return s;
}

}  // namespace glint
