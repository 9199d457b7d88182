// The passes of a time-budgeted render: doubling from one ray per pixel, never more than
// the time left allows, and the fixed size the user asked for with --spp.
#include <gtest/gtest.h>

#include "glint/camera/PassSchedule.hpp"

namespace glint {
namespace {

struct Simulated {
  long long rays = 0;
  int passes = 0;
  double seconds = 0.0;
};

// A budgeted render whose passes cost `overhead` seconds plus `perRay` seconds per ray
// per pixel, scheduled by `schedule`; every other pass runs `slowdown` times slower and
// `delay` seconds later (another process on the cores, taking them for a time slice).
Simulated Simulate(PassSchedule schedule, double budget, double perRay, double overhead,
                   double slowdown = 1.0, double delay = 0.0) {
  Simulated s;
  int rays = schedule.FirstRays();
  while (rays > 0) {
    const bool slow = s.passes % 2 == 1;
    const double pass = (overhead + perRay * rays) * (slow ? slowdown : 1.0) + (slow ? delay : 0.0);
    s.seconds += pass;
    s.rays += rays;
    ++s.passes;
    rays = schedule.Next(rays, pass, budget - s.seconds);
  }
  return s;
}

TEST(PassSchedule, DoublesFromOne) {
  PassSchedule schedule;
  EXPECT_EQ(schedule.FirstRays(), 1);
  EXPECT_EQ(schedule.Next(1, 0.01, 100.0), 2);
  EXPECT_EQ(schedule.Next(2, 0.02, 100.0), 4);
  EXPECT_EQ(schedule.Next(64, 0.64, 100.0), 128);
  EXPECT_EQ(schedule.Next(PassSchedule::kMaxRays, 40.96, 1e9), PassSchedule::kMaxRays);
}

TEST(PassSchedule, TakesNoMoreThanTheTimeLeftAllows) {
  PassSchedule schedule;
  EXPECT_EQ(schedule.Next(1, 0.01, 100.0), 2);  // the first pass: 0.01 s of set-up at most
  // 0.01 s per ray per pixel, half of 0.53 s left (less the 20 ms reserve) less 0.01 s:
  // 24 rays fit, not 32.
  EXPECT_EQ(schedule.Next(16, 0.16, 0.53), 24);
  EXPECT_EQ(schedule.Next(16, 0.16, 0.0602), 1);
  EXPECT_EQ(schedule.Next(16, 0.16, 0.0598), 0);  // not even one ray: stop
  EXPECT_EQ(schedule.Next(16, 0.16, -1.0), 0);
}

TEST(PassSchedule, FixedPassesAsLongAsOneFits) {
  PassSchedule schedule(8);
  EXPECT_EQ(schedule.FirstRays(), 8);
  EXPECT_EQ(schedule.Next(8, 0.08, 0.1001), 8);  // 0.08 s and the 20 ms reserve fit
  EXPECT_EQ(schedule.Next(8, 0.08, 0.0999), 0);
}

TEST(PassSchedule, FillsTheBudgetInFewPassesWithoutOverspending) {
  // 1 ms per ray per pixel and 2 ms of set-up per pass, 10 s: one ray per pass reaches
  // ~3 300 rays per pixel; doubling passes reach most of the ~9 900 possible.
  for (const double overhead : {0.0, 2e-3, 0.5}) {
    const Simulated s = Simulate(PassSchedule(), 10.0, 1e-3, overhead);
    EXPECT_LE(s.seconds, 10.0) << overhead;
    EXPECT_LE(s.passes, 40) << overhead;
  }
  const Simulated s = Simulate(PassSchedule(), 10.0, 1e-3, 2e-3);
  EXPECT_GE(s.rays, 9500);
  // A pass up to 1.9 times slower than the one before still ends within the budget.
  for (const double overhead : {0.0, 2e-3, 0.5}) {
    EXPECT_LE(Simulate(PassSchedule(), 10.0, 1e-3, overhead, 1.9).seconds, 10.0) << overhead;
  }
  // Nor does one that other processes hold up for a few time slices, however short the pass.
  const double held = 0.020;  // the reserve
  for (const double overhead : {0.0, 2e-3, 0.5}) {
    EXPECT_LE(Simulate(PassSchedule(), 10.0, 1e-3, overhead, 1.9, held).seconds, 10.0) << overhead;
    EXPECT_LE(Simulate(PassSchedule(), 0.5, 1e-5, overhead * 0.01, 1.0, held).seconds, 0.5)
        << overhead;
  }
  const Simulated ones = Simulate(PassSchedule(1), 10.0, 1e-3, 2e-3);
  EXPECT_LE(ones.seconds, 10.0);
  EXPECT_LT(ones.rays, 3400);
}

TEST(PassSchedule, APassTooQuickForTheClockDoesNotStopTheRender) {
  PassSchedule schedule;
  EXPECT_EQ(schedule.Next(1, 0.0, 1.0), 2);  // 0 s measured: no division by zero
  EXPECT_EQ(PassSchedule(4).Next(4, 0.0, 1.0), 4);
}

}  // namespace
}  // namespace glint
