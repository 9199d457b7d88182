// Whitted's local term at hits anywhere in the room, in SIMD lanes: for a lane's hit
// point, facing normal and material, each point light's direction and cos(theta), its
// shadow ray from the offset origin through the opaque spheres and cubes (Scene::Blocked
// without glass), and rho (kd / pi + ks (n + 2) / (2 pi) max(0, R . -d)^n) I cos(theta) /
// r^2, summed in the lights' order: WhittedIntegrator::LocalLight's operations in its
// order (CosinePower's squarings for the integer exponent n), so that every lane's colour
// is the scalar one to the bit. WhittedWallLanes is the camera ray's special case on a
// wall, with its shadow rays left to the pixel's shaft.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/sampling/Sampling.hpp"  // PowerBySquaring
#include "glint/scene/Scene.hpp"
#include "glint/transport/SegmentLanes.hpp"

namespace glint {

// What the lanes read and write, W wall hits at a time.
struct LocalLightLaneData {
  using Lane = RayLanes::Lane;
  // In: the hit point, its normal facing the ray, the ray's direction d; the material's
  // rho, kd / pi, ks (n + 2) / (2 pi), n, and 1 where it has a specular lobe (ks > 0).
  alignas(64) std::array<Lane, 3> point{}, normal{}, direction{}, reflectance{};
  alignas(64) Lane diffuse{}, specularScale{}, exponent{}, specular{};
  // Out: the local term, and how many shadow rays each lane cast.
  alignas(64) std::array<Lane, 3> colour{};
  alignas(64) Lane shadowRays{};
};

// The scene's numbers the lanes need, each as the scalar code holds it.
struct LocalLightLaneScene {
  struct LightTerms {
    std::array<double, 3> position, intensity;
  };
  std::vector<LightTerms> lights;
  SegmentLaneScene segments;  // the opaque spheres and cubes: shadow rays pass through glass
  int exponentBits = 0;       // of the largest exponent the lanes serve
};

using LocalLightKernel = void (*)(const LocalLightLaneScene&, LocalLightLaneData&, int);

class LocalLightLanes {
 public:
  // The lanes for `scene`'s point lights, on `target` (Auto: the widest the CPU runs);
  // throws std::invalid_argument naming the targets the CPU runs if it lacks `target`.
  LocalLightLanes(const Scene& scene, SimdTarget target);

  // Whether the lanes' term is LocalLight's for a hit on `m`: no specular lobe, or one
  // whose exponent CosinePower raises to by squaring (an integer in [0, 1024]).
  static bool Serves(const Material& m) {
    return !(m.whittedSpecular > 0.0) || PowerBySquaring(m.exponent);
  }
  // Lane j's material inputs, as LocalLight computes them from `m`.
  static void SetMaterial(LocalLightLaneData& lanes, std::size_t j, const Material& m);
  // Lanes [0, count) from their point, normal and diffuse: colour and shadowRays. Lanes
  // up to the next multiple of the width are overwritten with lane 0's.
  void Shade(LocalLightLaneData& lanes, int count) const;

 private:
  LocalLightLaneScene k_;
  int width_;
  LocalLightKernel kernel_;
};

}  // namespace glint
