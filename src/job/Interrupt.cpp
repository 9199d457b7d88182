#include "job/Interrupt.hpp"

#include <csignal>

namespace glint {

namespace {
std::atomic<bool> gInterrupted{false};
std::atomic<int> gSignal{0};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set in a signal handler");

extern "C" void OnSignal(int signal) {
  gSignal.store(signal, std::memory_order_relaxed);
  gInterrupted.store(true, std::memory_order_relaxed);
}
}  // namespace

const std::atomic<bool>& InstallInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return gInterrupted;
}

int InterruptSignal() {
  return gSignal.load(std::memory_order_relaxed);
}

}  // namespace glint
