// PCG32 (O'Neill 2014): a small, fast generator with independent streams. glint gives
// every pixel its own stream derived from (seed, pixel index), so an image does not
// depend on how pixels are shared among threads.
#pragma once

#include <cstdint>

namespace glint {

class Pcg32 {
 public:
  Pcg32(std::uint64_t seed, std::uint64_t stream) { Seed(seed, stream); }

  // The generator for one pass over one pixel of an image rendered with `seed`.
  static Pcg32 ForPixel(std::uint64_t seed, std::uint64_t pixelIndex, std::uint64_t pass = 0) {
    return Pcg32(SplitMix64(seed ^ SplitMix64(pixelIndex ^ SplitMix64(pass))), pixelIndex);
  }

  std::uint32_t NextU32() {
    const std::uint64_t old = state_;
    state_ = old * kMultiplier + inc_;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18U) ^ old) >> 27U);
    const auto rot = static_cast<std::uint32_t>(old >> 59U);
    return (xorshifted >> rot) | (xorshifted << ((32U - rot) & 31U));
  }

  // Uniform double in [0, 1) from one draw: the multiples of 2^-32, exact in a double,
  // as pbrt-v4 takes 32 bits for a uniform. Finer than any use here needs (a pixel
  // jitter of 2^-32 pixels, a Phong lobe's 1 - u1 >= 2^-32); two draws for 53 bits
  // cost 3% of a render (measured).
  double Uniform() { return static_cast<double>(NextU32()) * 0x1.0p-32; }

  static std::uint64_t SplitMix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
  }

 private:
  static constexpr std::uint64_t kMultiplier = 6364136223846793005ULL;

  void Seed(std::uint64_t seed, std::uint64_t stream) {
    state_ = 0;
    inc_ = (stream << 1U) | 1U;
    NextU32();
    state_ += seed;
    NextU32();
  }

  std::uint64_t state_ = 0;
  std::uint64_t inc_ = 1;
};

}  // namespace glint
