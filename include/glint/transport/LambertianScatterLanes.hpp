// The cosine-sampled child of a Lambertian hit, in SIMD lanes: for W hits at a time (the
// walls a lock-step step of MonteCarloIntegrator::TraceGroupFromLanes sends on), the
// child's direction from the hit's numbers u, v (SampleCosineDirection: Malley's method,
// SinCosTurns, Frame::FromZ, normalised) and its origin moved off the wall to the side it
// leaves on (OffsetRayOrigin). Each lane does the scalar code's operations in their order,
// so its ray is the scalar one to the bit on every target (`Scalar`: the same code at one
// lane).
#pragma once

#include <array>
#include <cstdint>

#include "glint/camera/RayLanes.hpp"
#include "glint/core/Math.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Sampler.hpp"

namespace glint {

// The children waiting for their ray, and the rays.
struct LambertianScatterLaneData {
  using Lane = RayLanes::Lane;
  // In: the hit point, the surface's normal, the normal facing the incident ray, the
  // scatter sample's numbers.
  alignas(64) std::array<Lane, 3> point{}, normal{}, facing{};
  alignas(64) Lane u{}, v{};
  // Out: the child's unit direction and its origin.
  alignas(64) std::array<Lane, 3> direction{}, start{};
  // Whose they are: the children's nodes in their trees, and how many wait.
  std::array<std::uint32_t, RayLanes::kMax> node{};
  int count = 0;

  // Writes a hit's inputs to the next lane without counting it (Russian roulette has not
  // yet kept the child); count < RayLanes::kMax.
  void Stage(vec3 p, vec3 surfaceNormal, vec3 facingNormal, Sample2 uv);
  // Counts the staged lane as tree node `child`'s.
  void Keep(std::uint32_t child) { node[static_cast<std::size_t>(count++)] = child; }
};

using LambertianScatterKernel = void (*)(LambertianScatterLaneData&, int);

class LambertianScatterLanes {
 public:
  // Throws std::invalid_argument naming the targets the CPU runs if it lacks `target`.
  explicit LambertianScatterLanes(SimdTarget target);

  // Lanes [0, lanes.count): direction and start. Lanes up to the next multiple of the
  // width are overwritten with lane 0's inputs, their results ignored.
  void Sample(LambertianScatterLaneData& lanes) const;

 private:
  int width_;
  LambertianScatterKernel kernel_;
};

}  // namespace glint
