// The Sobol sampler's first dimension group (the pixel point and the first light point,
// SampleDimension 0-3) of several consecutive samples at once, in SIMD lanes (Google
// Highway, the target chosen at run time; `Scalar` the same code at one lane). It is
// Sampler::StartSample's integer arithmetic, lane by lane: bit reversal, Burley's hash
// Owen scramble of the index, the Sobol4 tables, the scramble of each component. Integer
// operations round nothing, so every target gives the same bits.
#pragma once

#include <array>
#include <cstdint>

#include "glint/core/SimdTarget.hpp"

namespace glint {

struct SobolLaneSeeds {
  std::uint32_t shuffle;                   // the index's scramble
  std::array<std::uint32_t, 4> component;  // each component's
};

// At most this many samples a call.
inline constexpr int kSobolLanesMax = 8;
// The four components of each sample, as 32-bit fixed point ([0, 1) times 2^32).
using SobolLaneValues = std::array<std::array<std::uint32_t, kSobolLanesMax>, 4>;

// Samples firstIndex, firstIndex + 1, ... (count <= kSobolLanesMax) of a pixel whose
// first group has `seeds`, on `target` (resolved: not Auto; one the CPU runs).
void SobolFirstGroupLanes(SimdTarget target, const SobolLaneSeeds& seeds, std::uint32_t firstIndex,
                          int count, SobolLaneValues& out);

}  // namespace glint
