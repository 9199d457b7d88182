// The clocks of a timed run on a shared machine: wall time (what a user waits), this
// process's CPU time (getrusage: all its threads), and the core time every other process
// took meanwhile (the machine's busy time from /proc/stat, less this process's own). A
// timing taken while other work ran is not a fact about glint; this says how busy it was.
#pragma once

namespace glint {

struct Timing {
  double wall = 0.0;    // seconds
  double cpu = 0.0;     // seconds of CPU this process used (user + system, every thread)
  double others = 0.0;  // seconds of core time other processes used (0 where unknown)

  Timing& operator+=(const Timing& t) {
    wall += t.wall;
    cpu += t.cpu;
    others += t.others;
    return *this;
  }
  // Cores' worth of other work during the run: 0.5 is half a core taken.
  double OtherCores() const { return wall > 0.0 ? others / wall : 0.0; }
};

class RunClock {
 public:
  RunClock() { Restart(); }
  void Restart();
  // Since construction or the last Restart.
  Timing Elapsed() const;

  // The machine's busy core-seconds since boot (all cores), from /proc/stat; -1 without it.
  static double MachineBusySeconds();
  static double ProcessCpuSeconds();

 private:
  double wall0_ = 0.0;
  double cpu0_ = 0.0;
  double busy0_ = 0.0;
};

}  // namespace glint
