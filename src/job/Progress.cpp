#include "job/Progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace glint {

bool StderrIsTerminal() {
  return isatty(STDERR_FILENO) != 0;
}

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressBar::Update(double fraction, const char* label) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && fraction < 1.0 && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  drawn_ = true;
  constexpr int kWidth = 40;
  fraction = fraction < 0.0 ? 0.0 : (fraction > 1.0 ? 1.0 : fraction);
  const int filled = static_cast<int>(fraction * kWidth);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "\r[");
  for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : ' ', stderr);
  std::fprintf(stderr, "] %3d%%  %.1f s", static_cast<int>(100 * fraction), elapsed);
  if (fraction > 0.0 && fraction < 1.0) {
    std::fprintf(stderr, ", about %.1f s left", elapsed * (1.0 - fraction) / fraction);
  }
  std::fprintf(stderr, " %s   ", label);
  std::fflush(stderr);
}

void ProgressBar::Finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r%80s\r", "");
  std::fflush(stderr);
}

}  // namespace glint
