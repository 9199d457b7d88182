// Highway compiles this file once per x86-64 target (foreach_target.h); the kernel below
// is the same source for each, chosen at run time by SobolFirstGroupLanes.
#include "glint/sampling/SobolLanes.hpp"

#include <cstddef>
#include <cstdint>

#include "glint/sampling/LowDiscrepancy.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/sampling/SobolLanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace glint {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// ReverseBits32, lane by lane, by shifts and masks: for the one-lane path, whose
// partial register has no 16-byte table to look bytes up in.
template <class D, class V>
V ReverseBitsByShifts(D d, V x) {
  const auto k1 = hn::Set(d, 0x55555555U);
  const auto k2 = hn::Set(d, 0x33333333U);
  const auto k4 = hn::Set(d, 0x0f0f0f0fU);
  x = hn::Or(hn::And(hn::ShiftRight<1>(x), k1), hn::ShiftLeft<1>(hn::And(x, k1)));
  x = hn::Or(hn::And(hn::ShiftRight<2>(x), k2), hn::ShiftLeft<2>(hn::And(x, k2)));
  x = hn::Or(hn::And(hn::ShiftRight<4>(x), k4), hn::ShiftLeft<4>(hn::And(x, k4)));
  // __builtin_bswap32
  return hn::Or(hn::Or(hn::ShiftRight<24>(x), hn::And(hn::ShiftRight<8>(x), hn::Set(d, 0xff00U))),
                hn::Or(hn::And(hn::ShiftLeft<8>(x), hn::Set(d, 0xff0000U)), hn::ShiftLeft<24>(x)));
}

// ReverseBits32, lane by lane: each byte's two nibbles reversed and swapped by two
// in-register lookups of 16 bytes, then the bytes of each lane swapped by a third:
// 8 operations instead of the shifts' 22 (the Sobol lanes reverse 6 times a sample).
template <class D, class V>
V ReverseBits(D d, V x) {
  if constexpr (hn::MaxLanes(D()) < 4) {
    return ReverseBitsByShifts(d, x);
  } else {
    const hn::Repartition<std::uint8_t, D> d8;
    // Nibble i reversed, for a byte's low nibble (to its high half) and its high one.
    alignas(16) static constexpr std::uint8_t kLow[16] = {0x00, 0x80, 0x40, 0xc0, 0x20, 0xa0,
                                                          0x60, 0xe0, 0x10, 0x90, 0x50, 0xd0,
                                                          0x30, 0xb0, 0x70, 0xf0};
    alignas(16) static constexpr std::uint8_t kHigh[16] = {0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe,
                                                           0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf};
    alignas(16) static constexpr std::uint8_t kSwap[16] = {3,  2,  1, 0, 7,  6,  5,  4,
                                                           11, 10, 9, 8, 15, 14, 13, 12};
    const auto nibble = hn::Set(d, 0x0f0f0f0fU);
    const auto low = hn::BitCast(d8, hn::And(x, nibble));
    const auto high = hn::BitCast(d8, hn::And(hn::ShiftRight<4>(x), nibble));
    const auto bytes = hn::Or(hn::TableLookupBytes(hn::LoadDup128(d8, kLow), low),
                              hn::TableLookupBytes(hn::LoadDup128(d8, kHigh), high));
    return hn::BitCast(d, hn::TableLookupBytes(bytes, hn::LoadDup128(d8, kSwap)));
  }
}

// OwenScrambleReversed, lane by lane.
template <class D, class V>
V OwenScramble(D d, V v, std::uint32_t seed) {
  v = hn::Xor(v, hn::Mul(v, hn::Set(d, 0x3d20adeaU)));
  v = hn::Add(v, hn::Set(d, seed));
  v = hn::Mul(v, hn::Set(d, (seed >> 16U) | 1U));
  v = hn::Xor(v, hn::Mul(v, hn::Set(d, 0x05526c56U)));
  v = hn::Xor(v, hn::Mul(v, hn::Set(d, 0x53a22864U)));
  return v;
}

// Sobol4::SampleReversed(r, dim), lane by lane. Dimension 0's directions are the
// identity, so its point is ReverseBits(r). The others xor one table entry per byte of
// r: gathered from memory where a register holds fewer than 8 lanes, and where it holds
// 8, one entry per 3 bits looked up inside a register (Sobol4::OctalTableOf; 4 gathers
// cost more than 11 in-register lookups: measured in BENCHMARKS.md, "SIMD lanes").
template <class D, class V>
V SampleReversed(D d, V r, int dim) {
  if (dim == 0) return ReverseBits(d, r);
  if constexpr (hn::MaxLanes(D()) == 8) {
    const hn::RebindToSigned<D> di;
    const auto seven = hn::Set(d, 7U);
    auto x = hn::Zero(d);
    for (int k = 0; k < Sobol4::kOctalChunks; ++k) {
      const auto bits = hn::BitCast(di, hn::And(hn::ShiftRightSame(r, 3 * k), seven));
      const auto table = hn::Load(d, Sobol4::OctalTableOf(dim, k));
      x = hn::Xor(x, hn::TableLookupLanes(table, hn::IndicesFromVec(d, bits)));
    }
    return x;
  } else {
    const hn::RebindToSigned<D> di;
    const auto byte = hn::Set(d, 0xffU);
    const auto b0 = hn::BitCast(di, hn::And(r, byte));
    const auto b1 = hn::BitCast(di, hn::And(hn::ShiftRight<8>(r), byte));
    const auto b2 = hn::BitCast(di, hn::And(hn::ShiftRight<16>(r), byte));
    const auto b3 = hn::BitCast(di, hn::ShiftRight<24>(r));
    return hn::Xor(hn::Xor(hn::GatherIndex(d, Sobol4::TableOf(dim, 0), b0),
                           hn::GatherIndex(d, Sobol4::TableOf(dim, 1), b1)),
                   hn::Xor(hn::GatherIndex(d, Sobol4::TableOf(dim, 2), b2),
                           hn::GatherIndex(d, Sobol4::TableOf(dim, 3), b3)));
  }
}

template <class D>
void FirstGroupIn(D d, const SobolLaneSeeds& s, std::uint32_t firstIndex, int count,
                  SobolLaneValues& out) {
  const std::size_t w = hn::Lanes(d);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); i += w) {
    const auto index =
        hn::Add(hn::Set(d, firstIndex + static_cast<std::uint32_t>(i)), hn::Iota(d, 0));
    const auto shuffled = OwenScramble(d, ReverseBits(d, index), s.shuffle);
    for (std::size_t c = 0; c < 4; ++c) {
      const auto x = SampleReversed(d, shuffled, static_cast<int>(c));
      hn::StoreU(ReverseBits(d, OwenScramble(d, x, s.component[c])), d, out[c].data() + i);
    }
  }
}

// Eight 32-bit lanes where the target has them (AVX2, AVX-512 at half width), four on
// SSE4, and one: the scalar path, the same code.
void FirstGroupLanes(const SobolLaneSeeds& s, std::uint32_t firstIndex, int count,
                     SobolLaneValues& out) {
  FirstGroupIn(hn::CappedTag<std::uint32_t, kSobolLanesMax>(), s, firstIndex, count, out);
}
void FirstGroupLane(const SobolLaneSeeds& s, std::uint32_t firstIndex, int count,
                    SobolLaneValues& out) {
  FirstGroupIn(hn::CappedTag<std::uint32_t, 1>(), s, firstIndex, count, out);
}

// NOLINTNEXTLINE(google-readability-namespace-comments)
}  // namespace HWY_NAMESPACE
}  // namespace glint
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace glint {

void SobolFirstGroupLanes(SimdTarget target, const SobolLaneSeeds& seeds, std::uint32_t firstIndex,
                          int count, SobolLaneValues& out) {
  using Kernel = void (*)(const SobolLaneSeeds&, std::uint32_t, int, SobolLaneValues&);
  Kernel kernel = nullptr;
  switch (target) {
    case SimdTarget::Sse4:
      kernel = HWY_CHOOSE_SSE4(FirstGroupLanes);
      break;
    case SimdTarget::Avx2:
      kernel = HWY_CHOOSE_AVX2(FirstGroupLanes);
      break;
    case SimdTarget::Avx512:
      kernel = HWY_CHOOSE_AVX3(FirstGroupLanes);
      break;
    case SimdTarget::Auto:
    case SimdTarget::Scalar:
      break;
  }
  if (kernel == nullptr) kernel = &HWY_STATIC_DISPATCH(FirstGroupLane);
  kernel(seeds, firstIndex, count, out);
}

}  // namespace glint
#endif  // HWY_ONCE
