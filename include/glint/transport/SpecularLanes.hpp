// The directions Whitted's specular children take, in SIMD lanes: for a lane's incident
// direction d and outward normal n, the mirror direction normalize(Reflect(d, n)) and, for
// glass of index ior, CrossDielectric's refracted direction and Fresnel reflectance (1
// under total internal reflection), each with the scalar code's operations in its order,
// so that every lane's numbers are the scalar ones to the bit.
#pragma once

#include <array>

#include "glint/camera/RayLanes.hpp"
#include "glint/core/SimdTarget.hpp"

namespace glint {

struct SpecularLaneData {
  using Lane = RayLanes::Lane;
  // In: d, n (outward), the glass's index (any value for an opaque mirror).
  alignas(64) std::array<Lane, 3> direction{}, normal{};
  alignas(64) Lane ior{};
  // Out: the mirror direction; the refracted one, with 1 in `refracts` where there is
  // one (no total internal reflection); the Fresnel reflectance.
  alignas(64) std::array<Lane, 3> mirror{}, refracted{};
  alignas(64) Lane refracts{}, reflectance{};
};

using SpecularKernel = void (*)(SpecularLaneData&, int);

class SpecularLanes {
 public:
  // The lanes on `target` (Auto: the widest the CPU runs); throws std::invalid_argument
  // naming the targets the CPU runs if it lacks `target`.
  explicit SpecularLanes(SimdTarget target);

  // Lanes [0, count) from their direction, normal and ior. Lanes up to the next multiple
  // of the width are overwritten with lane 0's.
  void Find(SpecularLaneData& lanes, int count) const;

 private:
  int width_;
  SpecularKernel kernel_;
};

}  // namespace glint
