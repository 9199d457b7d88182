#include "glint/sampling/Sampler.hpp"

namespace glint {

std::optional<SamplerKind> ParseSamplerKind(std::string_view name) {
  if (name == "random") return SamplerKind::Random;
  if (name == "stratified") return SamplerKind::Stratified;
  if (name == "sobol") return SamplerKind::Sobol;
  return std::nullopt;
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
