// SobolLanes against the scalar Sobol sampler's first group (Sampler::FirstGroupValue's
// arithmetic, written out here from LowDiscrepancy.hpp): every target the CPU runs, every
// count of lanes, indices up to 2^32 - 1 and seeds of every bit pattern.
#include <gtest/gtest.h>

#include <cstdint>

#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/LowDiscrepancy.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/sampling/SobolLanes.hpp"

namespace glint {
namespace {

std::uint32_t ScalarComponent(const SobolLaneSeeds& s, std::uint32_t index, int c) {
  const std::uint32_t shuffled = OwenScrambleReversed(ReverseBits32(index), s.shuffle);
  const std::uint32_t x = Sobol4::SampleReversed(shuffled, c);
  return ReverseBits32(OwenScrambleReversed(x, s.component[static_cast<std::size_t>(c)]));
}

TEST(SobolLanes, EveryTargetGivesTheScalarSamplersBits) {
  Pcg32 rng(27, 3);
  int compared = 0;
  for (const SimdTarget target : SupportedSimdTargets()) {
    for (int trial = 0; trial < 2000; ++trial) {
      const SobolLaneSeeds seeds{rng.NextU32(),
                                 {rng.NextU32(), rng.NextU32(), rng.NextU32(), rng.NextU32()}};
      // Small indices (a pixel's first passes) and any 32-bit index, wrapping included.
      const std::uint32_t first = trial % 2 == 0 ? rng.NextU32() % 4096U : rng.NextU32();
      const int count = 1 + trial % kSobolLanesMax;
      SobolLaneValues values{};
      SobolFirstGroupLanes(target, seeds, first, count, values);
      for (int c = 0; c < 4; ++c) {
        for (int j = 0; j < count; ++j) {
          const std::uint32_t index = first + static_cast<std::uint32_t>(j);
          ASSERT_EQ(values[static_cast<std::size_t>(c)][static_cast<std::size_t>(j)],
                    ScalarComponent(seeds, index, c))
              << SimdTargetName(target) << ", index " << index << ", component " << c;
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 0);
}

// Every table entry, through single-bit indices: the lanes' tables and the byte tables
// agree on each bit of every dimension (a wrong entry for a high bit would hide from
// small indices).
TEST(SobolLanes, OctalTablesAgreeWithTheByteTablesBitByBit) {
  for (int d = 0; d < Sobol4::kDimensions; ++d) {
    for (int bit = 0; bit < 32; ++bit) {
      const std::uint32_t r = 1U << static_cast<unsigned>(bit);
      const std::uint32_t entry = Sobol4::OctalTableOf(d, bit / 3)[1U << (bit % 3)];
      EXPECT_EQ(entry, Sobol4::SampleReversed(r, d)) << "dimension " << d << ", bit " << bit;
    }
  }
}

}  // namespace
}  // namespace glint
