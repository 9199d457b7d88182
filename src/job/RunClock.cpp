#include "job/RunClock.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>

namespace glint {

namespace {

double WallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

double RunClock::ProcessCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// /proc/stat's first line: "cpu user nice system idle iowait irq softirq steal ..." in
// clock ticks summed over the cores; busy is everything but idle and iowait.
double RunClock::MachineBusySeconds() {
  std::ifstream in("/proc/stat");
  std::string cpu;
  double field[8] = {};
  if (!(in >> cpu) || cpu != "cpu") return -1.0;
  for (double& f : field) {
    if (!(in >> f)) return -1.0;
  }
  const double busy = field[0] + field[1] + field[2] + field[5] + field[6] + field[7];
  return busy / static_cast<double>(sysconf(_SC_CLK_TCK));
}

void RunClock::Restart() {
  wall0_ = WallSeconds();
  cpu0_ = ProcessCpuSeconds();
  busy0_ = MachineBusySeconds();
}

Timing RunClock::Elapsed() const {
  Timing t;
  t.wall = WallSeconds() - wall0_;
  t.cpu = ProcessCpuSeconds() - cpu0_;
  const double busy = MachineBusySeconds();
  // Ticks of 10 ms: over a short run this is coarse; sums over many runs are not.
  if (busy >= 0.0 && busy0_ >= 0.0) t.others = std::max(0.0, busy - busy0_ - t.cpu);
  return t;
}

}  // namespace glint
