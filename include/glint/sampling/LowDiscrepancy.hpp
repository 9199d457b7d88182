// The building blocks of the stratified and Sobol samplers: bit reversal, hash-based Owen
// scrambling (Burley 2020, "Practical Hash-based Owen Scrambling"), the first four
// dimensions of the Sobol sequence, and a permutation of [0, n) by a hash (Kensler 2013,
// "Correlated Multi-Jittered Sampling").
#pragma once

#include <array>
#include <cstdint>

namespace glint {

inline std::uint32_t ReverseBits32(std::uint32_t x) {
  x = ((x >> 1U) & 0x55555555U) | ((x & 0x55555555U) << 1U);
  x = ((x >> 2U) & 0x33333333U) | ((x & 0x33333333U) << 2U);
  x = ((x >> 4U) & 0x0f0f0f0fU) | ((x & 0x0f0f0f0fU) << 4U);
  return __builtin_bswap32(x);
}

// A 32-bit hash of two values (for seeds: one per pixel, per dimension group, per axis).
inline std::uint32_t MixBits(std::uint32_t a, std::uint32_t b) {
  std::uint64_t x = (static_cast<std::uint64_t>(a) << 32U) | b;
  x ^= x >> 31U;
  x *= 0x7fb5d329728ea185ULL;
  x ^= x >> 27U;
  x *= 0x81dadef4bc2dd44dULL;
  x ^= x >> 33U;
  return static_cast<std::uint32_t>(x);
}

// A random nested-uniform (Owen) scramble of a 32-bit fixed-point value, applied to the
// value with its bits reversed: then "flip bit k according to the bits above it" becomes
// "according to the bits below it", which is what adding, multiplying by an odd number
// and xoring with a multiple by an even number do. The constants are Burley's improved
// ones (as in pbrt-v4's FastOwenScrambler and Cycles' reversed_bit_owen).
inline std::uint32_t OwenScrambleReversed(std::uint32_t v, std::uint32_t seed) {
  v ^= v * 0x3d20adeaU;
  v += seed;
  v *= (seed >> 16U) | 1U;
  v ^= v * 0x05526c56U;
  v ^= v * 0x53a22864U;
  return v;
}
inline std::uint32_t OwenScramble(std::uint32_t v, std::uint32_t seed) {
  return ReverseBits32(OwenScrambleReversed(ReverseBits32(v), seed));
}

// The first four dimensions of the Sobol sequence as 32-bit fixed point: dimension 0 is
// van der Corput's, 1-3 come from the primitive polynomials x + 1, x^2 + x + 1 and
// x^3 + x + 1 with Joe and Kuo's initial direction numbers (1), (1, 3), (1, 3, 1).
// A point is the xor of the direction numbers of its index's set bits. The samplers work
// with bits reversed (the scrambles' domain, above), so the tables take the index with
// its bits reversed and give the point with its bits reversed, byte by byte: four lookups
// and no reversal, instead of a loop over the 32 bits of a scrambled index.
class Sobol4 {
 public:
  static constexpr int kDimensions = 4;

  // ReverseBits32(point of index ReverseBits32(reversedIndex)) in dimension d.
  static std::uint32_t SampleReversed(std::uint32_t reversedIndex, int d) {
    const ByteTables& t = Tables()[static_cast<std::size_t>(d)];
    return t[0][reversedIndex & 0xffU] ^ t[1][(reversedIndex >> 8U) & 0xffU] ^
           t[2][(reversedIndex >> 16U) & 0xffU] ^ t[3][reversedIndex >> 24U];
  }
  // Dimension d's table for byte k of a reversed index (SobolLanes gathers from it):
  // entry b is what that byte, equal to b, xors into the point.
  static const std::uint32_t* TableOf(int d, int k) {
    return Tables()[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)].data();
  }
  // Dimension d's table for bits 3k, 3k + 1, 3k + 2 of a reversed index (k < 11; the
  // last holds bits 30 and 31): entry b is what those bits, equal to b, xor into the
  // point. Eight entries fill one 256-bit register, where SobolLanes looks them up.
  static constexpr int kOctalChunks = 11;
  static const std::uint32_t* OctalTableOf(int d, int k) {
    return OctalTables()[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)].data();
  }
  // The point of `index` in dimension d, the plain way (a loop over the index's bits).
  static std::uint32_t Sample(std::uint32_t index, int d) {
    const std::array<std::uint32_t, 32> v = Directions(d);
    std::uint32_t x = 0;
    for (std::size_t k = 0; index != 0; ++k, index >>= 1U) {
      if ((index & 1U) != 0U) x ^= v[k];
    }
    return x;
  }

  // The direction numbers v_k (bit k of the index xors v_k into the point).
  static constexpr std::array<std::uint32_t, 32> Directions(int d) {
    std::array<std::uint32_t, 32> v{};
    if (d == 0) {
      for (std::size_t k = 0; k < 32; ++k) v[k] = 0x80000000U >> k;
      return v;
    }
    // Degree s, the polynomial's middle coefficients a, initial m_1..m_s.
    constexpr std::size_t kDegree[] = {0, 1, 2, 3};
    constexpr std::uint32_t kCoefficients[] = {0, 0, 1, 1};
    constexpr std::uint32_t kInitial[][3] = {{0, 0, 0}, {1, 0, 0}, {1, 3, 0}, {1, 3, 1}};
    const auto di = static_cast<std::size_t>(d);
    const std::size_t s = kDegree[di];
    const std::uint32_t a = kCoefficients[di];
    for (std::size_t k = 0; k < 32; ++k) {
      if (k < s) {
        v[k] = kInitial[di][k] << (31 - k);  // m_k / 2^k
        continue;
      }
      // Bratley and Fox's recurrence: v_k = v_{k-s} ^ (v_{k-s} >> s) ^ sum_j a_j v_{k-j}.
      v[k] = v[k - s] ^ (v[k - s] >> s);
      for (std::size_t j = 1; j < s; ++j) {
        if (((a >> (s - 1 - j)) & 1U) != 0U) v[k] ^= v[k - j];
      }
    }
    return v;
  }

 private:
  using ByteTables = std::array<std::array<std::uint32_t, 256>, 4>;

  // Bit p of a reversed index is bit 31 - p of the index: it xors in v_{31-p}, reversed.
  static constexpr ByteTables MakeTables(int d) {
    const std::array<std::uint32_t, 32> v = Directions(d);
    ByteTables t{};
    for (std::size_t byte = 0; byte < 4; ++byte) {
      for (std::uint32_t b = 0; b < 256; ++b) {
        std::uint32_t x = 0;
        for (std::size_t k = 0; k < 8; ++k) {
          if (((b >> k) & 1U) != 0U) x ^= ReverseBits32Constexpr(v[31 - (8 * byte + k)]);
        }
        t[byte][b] = x;
      }
    }
    return t;
  }
  static constexpr std::uint32_t ReverseBits32Constexpr(std::uint32_t x) {
    std::uint32_t r = 0;
    for (int k = 0; k < 32; ++k, x >>= 1U) r = (r << 1U) | (x & 1U);
    return r;
  }
  static const std::array<ByteTables, kDimensions>& Tables() {
    static constexpr std::array<ByteTables, kDimensions> kTables = {MakeTables(0), MakeTables(1),
                                                                    MakeTables(2), MakeTables(3)};
    return kTables;
  }
  using OctalTables_ = std::array<std::array<std::uint32_t, 8>, kOctalChunks>;
  static constexpr OctalTables_ MakeOctalTables(int d) {
    const std::array<std::uint32_t, 32> v = Directions(d);
    OctalTables_ t{};
    for (std::size_t chunk = 0; chunk < kOctalChunks; ++chunk) {
      for (std::uint32_t b = 0; b < 8; ++b) {
        std::uint32_t x = 0;
        for (std::size_t k = 0; k < 3 && 3 * chunk + k < 32; ++k) {
          if (((b >> k) & 1U) != 0U) x ^= ReverseBits32Constexpr(v[31 - (3 * chunk + k)]);
        }
        t[chunk][b] = x;
      }
    }
    return t;
  }
  static const std::array<OctalTables_, kDimensions>& OctalTables() {
    alignas(32) static constexpr std::array<OctalTables_, kDimensions> kTables = {
        MakeOctalTables(0), MakeOctalTables(1), MakeOctalTables(2), MakeOctalTables(3)};
    return kTables;
  }
};

// Element i of a random permutation of [0, n), the permutation chosen by `seed`, with no
// table: a hash that is a bijection on the next power of two, walked until it lands in
// [0, n) (Kensler 2013, section 3).
inline std::uint32_t PermutationElement(std::uint32_t i, std::uint32_t n, std::uint32_t seed) {
  if (n <= 1) return 0;
  std::uint32_t w = n - 1;
  w |= w >> 1U;
  w |= w >> 2U;
  w |= w >> 4U;
  w |= w >> 8U;
  w |= w >> 16U;
  do {
    i ^= seed;
    i *= 0xe170893dU;
    i ^= seed >> 16U;
    i ^= (i & w) >> 4U;
    i ^= seed >> 8U;
    i *= 0x0929eb3fU;
    i ^= seed >> 23U;
    i ^= (i & w) >> 1U;
    i *= 1U | seed >> 27U;
    i *= 0x6935fa69U;
    i ^= (i & w) >> 11U;
    i *= 0x74dcb303U;
    i ^= (i & w) >> 2U;
    i *= 0x9e501cc3U;
    i ^= (i & w) >> 2U;
    i *= 0xc860a3dfU;
    i &= w;
    i ^= i >> 5U;
  } while (i >= n);
  return (i + seed) % n;
}

}  // namespace glint
