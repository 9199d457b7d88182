#include "Progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace glint {

bool StderrIsTerminal() {
  return isatty(STDERR_FILENO) != 0;
}

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressBar::Update(std::size_t done, std::size_t total) {
  if (!enabled_ || total == 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  drawn_ = true;
  constexpr int kWidth = 40;
  const double fraction = static_cast<double>(done) / static_cast<double>(total);
  const int filled = static_cast<int>(fraction * kWidth);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "\r[");
  for (int i = 0; i < kWidth; ++i) std::fputc(i < filled ? '#' : ' ', stderr);
  if (fraction > 0.0 && done < total) {
    std::fprintf(stderr, "] %3d%%  %.1f s, about %.1f s left ", static_cast<int>(100 * fraction),
                 elapsed, elapsed * (1.0 - fraction) / fraction);
  } else {
    std::fprintf(stderr, "] %3d%%  %.1f s                 ", static_cast<int>(100 * fraction),
                 elapsed);
  }
  std::fflush(stderr);
}

void ProgressBar::Finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r%80s\r", "");
  std::fflush(stderr);
}

}  // namespace glint
