// SIGINT and SIGTERM stop a render cleanly: the handler only raises a flag that the
// render loop checks between pixels.
#pragma once

#include <atomic>

namespace glint {

// Installs the handlers (once) and returns the flag they raise.
const std::atomic<bool>& InstallInterruptHandlers();
// The signal that raised the flag, or 0.
int InterruptSignal();

}  // namespace glint
