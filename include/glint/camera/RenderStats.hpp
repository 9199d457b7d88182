// Counters of one render: rays by kind and samples dropped for being NaN or Inf.
#pragma once

#include <array>
#include <cstdint>

namespace glint {

struct RenderStats {
  std::uint64_t cameraRays = 0;
  std::uint64_t reflectedRays = 0;
  std::uint64_t refractedRays = 0;
  std::uint64_t diffuseRays = 0;
  std::uint64_t shadowRays = 0;        // shadow tests: traced, or answered by the shaft
  std::uint64_t nonFiniteSamples = 0;  // NaN or Inf samples, dropped before averaging
  // Of shadowRays, those whose answer (unblocked) the pixel's shaft knew in advance.
  std::uint64_t shadowRaysByShaft = 0;

  // The counters in a fixed order, for a checkpoint's header or an MPI message.
  using Counters = std::array<std::uint64_t, 7>;
  Counters ToCounters() const {
    return {cameraRays, reflectedRays,    refractedRays,    diffuseRays,
            shadowRays, nonFiniteSamples, shadowRaysByShaft};
  }
  static RenderStats FromCounters(const Counters& c) {
    RenderStats s;
    s.cameraRays = c[0];
    s.reflectedRays = c[1];
    s.refractedRays = c[2];
    s.diffuseRays = c[3];
    s.shadowRays = c[4];
    s.nonFiniteSamples = c[5];
    s.shadowRaysByShaft = c[6];
    return s;
  }

  // Rays traced through the scene: a shadow ray the shaft answered was not traced, and
  // throughput counts only these.
  std::uint64_t ShadowRaysTraced() const { return shadowRays - shadowRaysByShaft; }
  std::uint64_t TracedRays() const {
    return cameraRays + reflectedRays + refractedRays + diffuseRays + ShadowRaysTraced();
  }
  RenderStats& operator+=(const RenderStats& o) {
    cameraRays += o.cameraRays;
    reflectedRays += o.reflectedRays;
    refractedRays += o.refractedRays;
    diffuseRays += o.diffuseRays;
    shadowRays += o.shadowRays;
    nonFiniteSamples += o.nonFiniteSamples;
    shadowRaysByShaft += o.shadowRaysByShaft;
    return *this;
  }
};

}  // namespace glint
