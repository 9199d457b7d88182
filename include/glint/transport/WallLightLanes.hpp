// Whitted's local term at wall hits anywhere in the room, in SIMD lanes: for a lane's
// hit point and facing normal, each point light's direction and cos(theta), its shadow
// ray from the offset origin through the opaque spheres and cubes (Scene::Blocked
// without glass), and rho kd / pi * I cos(theta) / r^2, summed in the lights' order:
// WhittedIntegrator::LocalLight's operations for a wall (kd, no specular lobe) in its
// order, so that every lane's colour is the scalar one to the bit. WhittedWallLanes is
// the camera ray's special case, with its shadow rays left to the pixel's shaft.
#pragma once

#include <array>
#include <vector>

#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"
#include "glint/scene/Scene.hpp"

namespace glint {

// What the lanes read and write, W wall hits at a time.
struct WallLightLaneData {
  using Lane = RayLanes::Lane;
  // In: the hit point, its normal facing the ray, rho kd / pi per colour channel.
  alignas(64) std::array<Lane, 3> point{}, normal{}, diffuse{};
  // Out: the local term, and how many shadow rays each lane cast.
  alignas(64) std::array<Lane, 3> colour{};
  alignas(64) Lane shadowRays{};
};

// The scene's numbers the lanes need, each as the scalar code holds it.
struct WallLightLaneScene {
  struct LightTerms {
    std::array<double, 3> position, intensity;
  };
  std::vector<LightTerms> lights;
  struct SphereTerms {
    std::array<double, 3> centre;
    double r2;  // radius * radius
  };
  std::vector<SphereTerms> spheres;  // the opaque ones
  struct CubeTerms {
    std::array<double, 3> centre, low, high;
    double boundRadius2;
  };
  std::vector<CubeTerms> cubes;  // the opaque ones
};

using WallLightKernel = void (*)(const WallLightLaneScene&, WallLightLaneData&, int);

class WallLightLanes {
 public:
  // The lanes for `scene`'s point lights, on `target` (Auto: the widest the CPU runs);
  // throws std::invalid_argument naming the targets the CPU runs if it lacks `target`.
  WallLightLanes(const Scene& scene, SimdTarget target);

  // Whether the lanes' term is LocalLight's for a hit on `m`: Lambertian, no specular lobe.
  static bool Serves(const Material& m) {
    return m.type == MaterialType::Lambertian && !(m.whittedSpecular > 0.0);
  }
  int Width() const { return width_; }
  // Lanes [0, count) from their point, normal and diffuse: colour and shadowRays. Lanes
  // up to the next multiple of the width are overwritten with lane 0's.
  void Shade(WallLightLaneData& lanes, int count) const;

 private:
  WallLightLaneScene k_;
  int width_;
  WallLightKernel kernel_;
};

}  // namespace glint
