// The instruction set the lock-step lanes (RayLanes) run on. One binary holds every
// x86-64 target (Google Highway's run-time dispatch); `Auto` takes the widest the CPU
// has, `Scalar` the same code at one lane. Every target gives the same bits.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

enum class SimdTarget { Auto, Scalar, Sse4, Avx2, Avx512 };

std::optional<SimdTarget> ParseSimdTarget(std::string_view name);
const char* SimdTargetName(SimdTarget target);
// Doubles per lane group: 1, 2, 4, 8 (Auto: the target it resolves to).
int SimdLanes(SimdTarget target);
// Whether this CPU runs `target` (Auto and Scalar: always).
bool SimdTargetSupported(SimdTarget target);
// The targets this CPU runs, scalar first, widest last.
std::vector<SimdTarget> SupportedSimdTargets();
// Auto becomes the widest supported target; the others stay.
SimdTarget ResolveSimdTarget(SimdTarget target);
// "scalar, sse4, avx2, avx512": the supported targets' names, for messages.
std::string SupportedSimdTargetNames();

// Throws as KernelForTarget does, unless the CPU runs `target` and it is `compiled`.
void RequireSimdTarget(SimdTarget target, bool compiled);

// A lane kernel's version for `target` (resolved) among one per target (Highway's
// HWY_CHOOSE_*, null where not compiled in; `scalar` is the one-lane form); throws
// std::invalid_argument naming the targets this CPU runs if it does not run `target`.
template <class Kernel>
Kernel KernelForTarget(SimdTarget target, Kernel sse4, Kernel avx2, Kernel avx512, Kernel scalar) {
  Kernel k = scalar;
  if (target == SimdTarget::Sse4) k = sse4;
  if (target == SimdTarget::Avx2) k = avx2;
  if (target == SimdTarget::Avx512) k = avx512;
  RequireSimdTarget(target, k != nullptr);
  return k;
}

}  // namespace glint
