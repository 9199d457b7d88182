#include "glint/sampling/Sampler.hpp"

namespace glint {

std::optional<SamplerKind> ParseSamplerKind(std::string_view name) {
  if (name == "random") return SamplerKind::Random;
  if (name == "stratified") return SamplerKind::Stratified;
  if (name == "sobol") return SamplerKind::Sobol;
  return std::nullopt;
}

void Sampler::FirstGroupInLanes(int first, int count, SimdTarget target,
                                std::array<std::array<double, kSobolLanesMax>, 4>& out,
                                bool lightPoint) {
  if (kind_ != SamplerKind::Sobol) {
    for (int j = 0; j < count; ++j) {
      const auto lane = static_cast<std::size_t>(j);
      StartSample(first + j);
      const Sample2 p = Get2D(SampleDimension::kPixel);
      const Sample2 l = lightPoint ? Get2D(SampleDimension::Light(0)) : Sample2{0.0, 0.0};
      out[0][lane] = p.u;
      out[1][lane] = p.v;
      out[2][lane] = l.u;
      out[3][lane] = l.v;
    }
    return;
  }
  FirstGroupsInLanes(first, count, target, out);
  // The state StartSample(first + count - 1) leaves (its first group from the lanes).
  StartSampleWith(first + count - 1, out, static_cast<std::size_t>(count - 1));
}

void Sampler::FirstGroupsInLanes(int first, int count, SimdTarget target,
                                 std::array<std::array<double, kSobolLanesMax>, 4>& out) const {
  const SobolLaneSeeds seeds{cached_[0].shuffle, cached_[0].component};
  SobolLaneValues values;
  SobolFirstGroupLanes(target, seeds,
                       static_cast<std::uint32_t>(firstSample_ + static_cast<std::uint64_t>(first)),
                       count, values);
  for (std::size_t c = 0; c < 4; ++c) {
    for (std::size_t j = 0; j < static_cast<std::size_t>(count); ++j)
      out[c][j] = ToUnit(values[c][j]);
  }
}

const char* SamplerName(SamplerKind kind) {
  switch (kind) {
    case SamplerKind::Random:
      return "random";
    case SamplerKind::Stratified:
      return "stratified";
    case SamplerKind::Sobol:
      return "sobol";
  }
  return "random";
}

}  // namespace glint
