// Where a path's random numbers come from. A pixel makes one Sampler per pass and asks it,
// for each of its samples, for the numbers of each decision by dimension (SampleDimension):
//   random      independent PCG32 uniforms: the design's "random number generator";
//   stratified  jittered strata for the pixel point and the first hit's light point and
//               scattering direction (where the pass's rays allow), independent beyond;
//   sobol       an Owen-scrambled Sobol sequence per pixel (Burley 2020): dimensions in
//               groups of four, each group the first four Sobol dimensions with its own
//               scramble and its own shuffle of the sample index ("shuffled padding", so
//               that groups are uncorrelated), every pixel its own seeds; beyond the first
//               groups, independent uniforms (kCachedGroups). A progressive render's
//               passes continue one sequence (Sampler's firstSample).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/LowDiscrepancy.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/sampling/SobolLanes.hpp"

namespace glint {

enum class SamplerKind { Random, Stratified, Sobol };

std::optional<SamplerKind> ParseSamplerKind(std::string_view name);
const char* SamplerName(SamplerKind kind);

// The dimension of each decision of one camera ray's path. Node k of its ray tree (k = the
// node's index less the root's, in the order the tree is traced; k = 0 is the camera ray)
// has six: its hit's light point, its scattering direction, the glass's choice and the
// Russian roulette of its first child. With the pixel point first, the pixel and the first
// light point share one group of four Sobol dimensions, the first direction the next.
struct SampleDimension {
  static constexpr std::uint32_t kPixel = 0;
  static constexpr std::uint32_t Light(std::uint32_t node) { return 2 + 6 * node; }
  static constexpr std::uint32_t Scatter(std::uint32_t node) { return 4 + 6 * node; }
  static constexpr std::uint32_t Choice(std::uint32_t node) { return 6 + 6 * node; }
  static constexpr std::uint32_t Roulette(std::uint32_t node) { return 7 + 6 * node; }
  // A Phong branch's direction (dimensions +0, +1) and roulette (+2) beyond the first.
  static constexpr std::uint32_t Extra(std::uint32_t node, std::uint32_t branch) {
    return (1U << 24U) + 4 * (64 * node + branch);
  }
  // A Lambertian node's light seen in mirrors (MirroredLight): its light point (+0, +1)
  // and whether to estimate it at all (+2). Lambertian nodes have no Phong branches, so
  // it takes a second branch's dimensions.
  static constexpr std::uint32_t MirroredLight(std::uint32_t node) { return Extra(node, 1); }
};

struct Sample2 {
  double u, v;
};

class Sampler {
 public:
  // The first dimension groups of up to kSobolLanesMax samples, out[c][j] for sample
  // first + j (FirstGroupsInLanes).
  using FirstGroups = std::array<std::array<double, kSobolLanesMax>, 4>;

  // The sampler of pixel `pixelIndex` for the pass `pass` of a render with `seed`, whose
  // `samplesInPass` samples are the pixel's samples firstSample, firstSample + 1, ...
  Sampler(SamplerKind kind, std::uint64_t seed, std::uint64_t pixelIndex, std::uint32_t pass,
          std::uint64_t firstSample, int samplesInPass)
      : kind_(kind),
        rng_(Pcg32::ForPixel(seed, pixelIndex, pass)),
        pixelSeed_(
            static_cast<std::uint32_t>(Pcg32::SplitMix64(seed ^ Pcg32::SplitMix64(pixelIndex)))),
        passSeed_(MixBits(pixelSeed_, pass)),
        firstSample_(firstSample),
        samples_(samplesInPass > 0 ? static_cast<std::uint32_t>(samplesInPass) : 1U) {
    if (kind_ == SamplerKind::Stratified) {
      // Strata of the pass: columns x rows = samples, columns the largest divisor <= sqrt.
      for (std::uint32_t c = 1; c * c <= samples_; ++c) {
        if (samples_ % c == 0) columns_ = c;
      }
    }
    if (kind_ == SamplerKind::Sobol) {
      for (std::uint32_t g = 0; g < kCachedGroups; ++g) cached_[g] = MakeGroupSeeds(g);
    }
  }

  // The random sampler drawing from `rng` (for tests that follow one stream).
  explicit Sampler(Pcg32 rng) : Sampler(SamplerKind::Random, 0, 0, 0, 0, 1) { rng_ = rng; }

  SamplerKind Kind() const { return kind_; }
  Pcg32 Generator() const { return rng_; }  // where the random sampler's stream has got to

  // The i-th sample of the pass begins.
  void StartSample(int i) {
    inPass_ = static_cast<std::uint32_t>(i);
    reversedIndex_ = ReverseBits32(static_cast<std::uint32_t>(firstSample_ + inPass_));
    if (kind_ == SamplerKind::Sobol) {
      // The first group (the pixel point and the first light point) all at once: four
      // independent hash chains that the processor overlaps.
      const std::uint32_t index = ShuffledIndex(cached_[0]);
      for (std::uint32_t c = 0; c < 4; ++c) firstGroup_[c] = SobolValue(cached_[0], index, c);
      paddingReady_ = false;
    }
  }

  // The numbers of the first two dimension pairs (SampleDimension::kPixel and
  // Light(0)) of samples first, first + 1, ... (count <= kSobolLanesMax): out[0..3][j]
  // are sample first + j's kPixel u, v and Light(0) u, v, what StartSample(first + j) and
  // two Get2D calls give (one, without `lightPoint`: out[2..3] are then 0). Sobol's come
  // from SIMD lanes on `target` (resolved, supported); the others' one by one, in the same
  // order. Leaves the sampler as those calls would.
  void FirstGroupInLanes(int first, int count, SimdTarget target,
                         std::array<std::array<double, kSobolLanesMax>, 4>& out,
                         bool lightPoint = true);

  // Sobol only: the first dimension groups (SampleDimension::kPixel and Light(0)) of
  // samples first, first + 1, ... (count <= kSobolLanesMax), out[0..3][j] for sample
  // first + j, from SIMD lanes on `target`, leaving the sampler as it was;
  // StartSampleWith(first + j, out[.][j]) then starts each sample as StartSample would.
  void FirstGroupsInLanes(int first, int count, SimdTarget target,
                          std::array<std::array<double, kSobolLanesMax>, 4>& out) const;
  void StartSampleWith(int i, const std::array<std::array<double, kSobolLanesMax>, 4>& groups,
                       std::size_t lane) {
    inPass_ = static_cast<std::uint32_t>(i);
    reversedIndex_ = ReverseBits32(static_cast<std::uint32_t>(firstSample_ + inPass_));
    for (std::size_t c = 0; c < 4; ++c) firstGroup_[c] = groups[c][lane];
    paddingReady_ = false;
  }

  double Get1D(std::uint32_t dimension) {
    if (kind_ == SamplerKind::Sobol) {
      if (dimension < 4) return firstGroup_[dimension];
      if (dimension >= kSobolDimensions) return Padding();
      const GroupSeeds seeds = cached_[dimension >> 2U];
      return SobolValue(seeds, ShuffledIndex(seeds), dimension & 3U);
    }
    return rng_.Uniform();
  }

  Sample2 Get2D(std::uint32_t dimension) {
    switch (kind_) {
      case SamplerKind::Random:
        break;
      case SamplerKind::Stratified:
        if (dimension <= SampleDimension::Scatter(0) && samples_ > 1) return Stratum(dimension);
        break;
      case SamplerKind::Sobol:
        if (dimension < 3) return {firstGroup_[dimension], firstGroup_[dimension + 1]};
        if (dimension + 1 >= kSobolDimensions || (dimension & 3U) == 3U) {
          const double u = Get1D(dimension);
          return {u, Get1D(dimension + 1)};
        }
        {  // both in one group: one shuffle of the index
          const GroupSeeds seeds = cached_[dimension >> 2U];
          const std::uint32_t index = ShuffledIndex(seeds);
          return {SobolValue(seeds, index, dimension & 3U),
                  SobolValue(seeds, index, (dimension & 3U) + 1)};
        }
    }
    const double u = rng_.Uniform();  // named: the order of the two draws is fixed
    const double v = rng_.Uniform();
    return {u, v};
  }

 private:
  static double ToUnit(std::uint32_t x) { return static_cast<double>(x) * 0x1.0p-32; }

  // A dimension group's seeds in this pixel: the index shuffle's and each component's.
  struct GroupSeeds {
    std::uint32_t shuffle;
    std::array<std::uint32_t, 4> component;
  };
  // Sobol's groups cover the pixel and the first two nodes of a path (SampleDimension),
  // their seeds made once a pixel and pass, the first group's point once a sample.
  // Deeper decisions take independent uniforms from a stream of the sample's own
  // (uncorrelated, like shuffled Sobol groups). With diffuse walls, Sobol groups for every
  // node traced 22% fewer rays/s than random (bench/equal-time), for the first five nodes
  // 18% fewer rays per pixel in a 7.3 s budget, for the first two 6% (189-196 against
  // 205-206, relative MSE 0.034 for both), while terminal walls keep Sobol's lead.
  static constexpr std::uint32_t kCachedGroups = 4;
  static constexpr std::uint32_t kSobolDimensions = 4 * kCachedGroups;

  double Padding() {
    if (!paddingReady_) {
      const std::uint32_t index = ReverseBits32(reversedIndex_);
      rng_ = Pcg32(Pcg32::SplitMix64((static_cast<std::uint64_t>(pixelSeed_) << 32U) | index),
                   pixelSeed_);
      paddingReady_ = true;
    }
    return rng_.Uniform();
  }

  GroupSeeds MakeGroupSeeds(std::uint32_t group) const {
    GroupSeeds s{};
    s.shuffle = MixBits(pixelSeed_, group);
    for (std::uint32_t c = 0; c < 4; ++c) s.component[c] = MixBits(s.shuffle, c + 1);
    return s;
  }
  // The sample's index shuffled for the group (Owen-scrambled: the first 2^k samples of
  // the pixel still take the first 2^k points), bits reversed.
  std::uint32_t ShuffledIndex(const GroupSeeds& seeds) const {
    return OwenScrambleReversed(reversedIndex_, seeds.shuffle);
  }
  // Component c of the group's scrambled point for that index, in [0, 1).
  __attribute__((always_inline)) static double SobolValue(const GroupSeeds& seeds,
                                                          std::uint32_t shuffledReversed,
                                                          std::uint32_t c) {
    const std::uint32_t x = Sobol4::SampleReversed(shuffledReversed, static_cast<int>(c));
    return ToUnit(ReverseBits32(OwenScrambleReversed(x, seeds.component[c])));
  }

  // A jittered point in this sample's stratum of the pass, for a pair of dimensions that
  // is stratified: the strata are dealt out to the samples by a permutation of its own
  // for each pair, so that the pairs are not correlated with one another.
  Sample2 Stratum(std::uint32_t dimension) {
    const std::uint32_t s = PermutationElement(inPass_, samples_, MixBits(passSeed_, dimension));
    const std::uint32_t rows = samples_ / columns_;
    const std::uint32_t column = s % columns_;
    const std::uint32_t row = s / columns_;
    const double u = (column + rng_.Uniform()) / columns_;
    const double v = (row + rng_.Uniform()) / rows;
    return {u, v};
  }

  SamplerKind kind_;
  Pcg32 rng_;                // random, the jitter of stratified, sobol's padding
  std::uint32_t pixelSeed_;  // sobol's scrambles
  std::uint32_t passSeed_;   // stratified's permutations
  std::uint64_t firstSample_;
  std::uint32_t samples_;
  std::uint32_t columns_ = 1;
  std::uint32_t inPass_ = 0;
  std::uint32_t reversedIndex_ = 0;     // the sample's number in the pixel, bits reversed
  std::array<double, 4> firstGroup_{};  // the first group's point of this sample
  std::array<GroupSeeds, kCachedGroups> cached_{};
  bool paddingReady_ = false;  // rng_ seeded for this sample's padding
};

}  // namespace glint
