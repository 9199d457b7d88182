// Next-event estimation at Lambertian hits in SIMD lanes: for W hits at a time (the walls
// a lock-step step of MonteCarloIntegrator::TraceGroupFromLanes meets), the light point of
// each hit's numbers u, v, the estimate Le (rho / pi) (n.x) (-n_y.x) A / r^4 and its shadow
// segment from the offset origin through every sphere and cube (Scene::Occluded: glass
// blocks). Each lane does DirectLightLambertian's and ShadowBlocked's operations in their
// order, so its colour is the scalar one to the bit on every target (`Scalar`: the same
// code at one lane).
#pragma once

#include <array>
#include <cstdint>

#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Sampler.hpp"
#include "glint/scene/Light.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/SegmentLanes.hpp"

namespace glint {

// The hits waiting for their estimate, and the estimates.
struct LambertianLightLaneData {
  using Lane = RayLanes::Lane;
  // In: the hit point, its normal facing the ray, the light's Le times the surface's rho,
  // the light sample's numbers, and 1 where the pixel's shaft sees all of the light (no test).
  alignas(64) std::array<Lane, 3> point{}, normal{}, radiance{};
  alignas(64) Lane u{}, v{}, unoccluded{};
  // Out: the estimate, and 1 where a shadow ray was cast (ShadowBlocked was reached).
  alignas(64) std::array<Lane, 3> colour{};
  alignas(64) Lane cast{};
  // Whose they are: the hits' nodes in their trees, and how many wait.
  std::array<std::uint32_t, RayLanes::kMax> node{};
  int count = 0;

  // Adds tree node `index`'s hit at p (normal n facing the ray), of Le rho `leRho`, for
  // the light point of the numbers uv; `shaftAnswered`: its shadow ray needs no test
  // (unoccluded). count < RayLanes::kMax.
  void Add(std::uint32_t index, vec3 p, vec3 n, Colour leRho, Sample2 uv, bool shaftAnswered);
};

// The light's and the blockers' numbers, each as the scalar code holds it.
struct LambertianLightLaneScene {
  std::array<double, 3> corner, edgeA, edgeB, normal;
  double area;
  SegmentLaneScene blockers;
};

using LambertianLightKernel = void (*)(const LambertianLightLaneScene&, LambertianLightLaneData&,
                                       int);

class LambertianLightLanes {
 public:
  // Throws std::invalid_argument naming the targets the CPU runs if it lacks `target`.
  LambertianLightLanes(const Scene& scene, const Light& light, SimdTarget target);

  // Lanes [0, lanes.count): colour and cast. Lanes up to the next multiple of the width
  // are overwritten with lane 0's inputs, their results ignored.
  void Estimate(LambertianLightLaneData& lanes) const;

 private:
  LambertianLightLaneScene k_;
  int width_;
  LambertianLightKernel kernel_;
};

}  // namespace glint
