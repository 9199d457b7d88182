#include "glint/core/SimdTarget.hpp"

#include <stdexcept>

#include <hwy/targets.h>

#include <array>
#include <cstdint>

namespace glint {

namespace {
struct TargetName {
  SimdTarget target;
  const char* name;
  int lanes;
  std::int64_t hwyTarget;  // Highway's bit; 0: needs none
};
constexpr std::array<TargetName, 5> kTargets = {{
    {SimdTarget::Auto, "auto", 0, 0},
    {SimdTarget::Scalar, "scalar", 1, 0},
    {SimdTarget::Sse4, "sse4", 2, HWY_SSE4},
    {SimdTarget::Avx2, "avx2", 4, HWY_AVX2},
    {SimdTarget::Avx512, "avx512", 8, HWY_AVX3},
}};

const TargetName& Entry(SimdTarget target) {
  for (const TargetName& t : kTargets) {
    if (t.target == target) return t;
  }
  return kTargets[1];
}
}  // namespace

std::optional<SimdTarget> ParseSimdTarget(std::string_view name) {
  for (const TargetName& t : kTargets) {
    if (name == t.name) return t.target;
  }
  return std::nullopt;
}

const char* SimdTargetName(SimdTarget target) {
  return Entry(target).name;
}

int SimdLanes(SimdTarget target) {
  return Entry(ResolveSimdTarget(target)).lanes;
}

bool SimdTargetSupported(SimdTarget target) {
  const std::int64_t bit = Entry(target).hwyTarget;
  return bit == 0 || (hwy::SupportedTargets() & bit) != 0;
}

std::vector<SimdTarget> SupportedSimdTargets() {
  std::vector<SimdTarget> out;
  for (const TargetName& t : kTargets) {
    if (t.target != SimdTarget::Auto && SimdTargetSupported(t.target)) out.push_back(t.target);
  }
  return out;
}

SimdTarget ResolveSimdTarget(SimdTarget target) {
  return target == SimdTarget::Auto ? SupportedSimdTargets().back() : target;
}

std::string SupportedSimdTargetNames() {
  std::string names;
  for (const SimdTarget t : SupportedSimdTargets()) {
    if (!names.empty()) names += ", ";
    names += SimdTargetName(t);
  }
  return names;
}

void RequireSimdTarget(SimdTarget target, bool compiled) {
  if (!SimdTargetSupported(target) || !compiled) {
    throw std::invalid_argument(std::string("this CPU does not run SIMD target '") +
                                SimdTargetName(target) +
                                "'; it runs: " + SupportedSimdTargetNames());
  }
}

}  // namespace glint
