// The rays per pixel of each pass of a render against a time budget (`--time`).
// A pass of one ray per pixel gives a first image at once but runs at 70-85% of the
// throughput of a pass of 64 (each pass seeds every pixel again and ends with a wait for
// the slowest thread), so passes double: 1, 2, 4, ... A pass takes no more rays than
// fit in half the time left. The prediction for n rays, n c + o, overestimates: c is the
// last pass's seconds per ray per pixel (its set-up included) and o the first pass's
// seconds (all of a pass's set-up and more); the half leaves room for a pass that runs
// slower than the one before (another process on the cores), so the last passes shrink
// and the budget is not overspent. A few of the scheduler's time slices, kReserveSeconds,
// are kept back from the time left as well: another process may take the core for that
// long in the middle of a pass, however short the pass (measured: 0.5 s budgets overspent by
// 1 ms in 2 of 6 runs of the test suite without it; with 4 ms, 0.24 ms once in a CI run
// on 2 cores, where other tests' threads queue for both: 20 ms covers a few slices). At
// most two one-ray passes' time and the reserve are left unused.
#pragma once

#include <algorithm>
#include <cmath>

namespace glint {

class PassSchedule {
 public:
  static constexpr int kMaxRays = 4096;             // a pass of at most this many rays per pixel
  static constexpr double kReserveSeconds = 0.020;  // a few time slices of the scheduler

  // fixedRays > 0: every pass has that many rays per pixel (the user's --spp), as long
  // as the last pass's time fits in what is left; 0: doubling passes.
  explicit PassSchedule(int fixedRays = 0) : fixedRays_(fixedRays) {}

  int FirstRays() const { return fixedRays_ > 0 ? fixedRays_ : 1; }

  // Records the pass just finished (`lastRays` rays per pixel in `lastSeconds`) and
  // returns the next pass's rays per pixel with `secondsLeft` of the budget left; 0 when
  // not even the smallest pass fits in half of it.
  int Next(int lastRays, double lastSeconds, double secondsLeft) {
    lastSeconds = std::max(lastSeconds, 0.0);
    const double usable = secondsLeft - kReserveSeconds;
    if (fixedRays_ > 0) return lastSeconds <= usable ? fixedRays_ : 0;
    if (overhead_ < 0.0) overhead_ = lastSeconds;  // the first pass
    const double perRay = lastSeconds / std::max(lastRays, 1);
    const double time = 0.5 * usable - overhead_;
    const double fits = perRay > 0.0 ? std::floor(time / perRay) : double{kMaxRays};
    const double rays = std::min({2.0 * lastRays, fits, double{kMaxRays}});
    return time >= 0.0 && rays >= 1.0 ? static_cast<int>(rays) : 0;
  }

 private:
  int fixedRays_;
  double overhead_ = -1.0;  // seconds of the first pass, once it is known
};

}  // namespace glint
