// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include <chrono>
#include <cstddef>

namespace glint {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled);
  // Redraws at most ten times a second; fraction in [0, 1], label after the bar.
  void Update(double fraction, const char* label = "");
  // Clears the line.
  void Finish();

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

// True if stderr is a terminal.
bool StderrIsTerminal();

}  // namespace glint
