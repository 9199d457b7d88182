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

}  // namespace glint
