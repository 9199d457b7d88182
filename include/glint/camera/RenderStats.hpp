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
  // Light tracing (--caustics light): the light paths' rays (from the light, and on
  // from each surface they scatter at), and the connections to the eye that added to a
  // pixel (their visibility tests count as shadow rays).
  std::uint64_t lightRays = 0;
  std::uint64_t splats = 0;
  // Of cameraRays, those traced in lock-step SIMD lanes (Integrator::TraceLanes) or whose
  // first hit the lanes found (Integrator::FindFirstHits).
  std::uint64_t laneRays = 0;

  // The counters in a fixed order, for a checkpoint's header or an MPI message.
  using Counters = std::array<std::uint64_t, 10>;
  Counters ToCounters() const {
    return {cameraRays,       reflectedRays,     refractedRays, diffuseRays, shadowRays,
            nonFiniteSamples, shadowRaysByShaft, lightRays,     splats,      laneRays};
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
    s.lightRays = c[7];
    s.splats = c[8];
    s.laneRays = c[9];
    return s;
  }

  // Rays traced through the scene: a shadow ray the shaft answered was not traced, and
  // throughput counts only these.
  std::uint64_t ShadowRaysTraced() const { return shadowRays - shadowRaysByShaft; }
  std::uint64_t TracedRays() const {
    return cameraRays + reflectedRays + refractedRays + diffuseRays + ShadowRaysTraced() +
           lightRays;
  }
  RenderStats& operator+=(const RenderStats& o) {
    cameraRays += o.cameraRays;
    reflectedRays += o.reflectedRays;
    refractedRays += o.refractedRays;
    diffuseRays += o.diffuseRays;
    shadowRays += o.shadowRays;
    nonFiniteSamples += o.nonFiniteSamples;
    shadowRaysByShaft += o.shadowRaysByShaft;
    lightRays += o.lightRays;
    splats += o.splats;
    laneRays += o.laneRays;
    return *this;
  }
};

}  // namespace glint
