// What a surface does with light. The scene has four kinds (spec, "Objects"):
// Lambertian walls, Phong objects (mirrors in Whitted mode, the normalised Phong BRDF in
// Monte Carlo mode), perfect mirrors, and glass.
#pragma once

#include <cstdint>

#include "glint/core/Math.hpp"

namespace glint {

enum class MaterialType : std::uint8_t { Lambertian, Phong, Mirror, Glass };

struct Material {
  MaterialType type = MaterialType::Lambertian;
  Colour reflectance{0.75};  // Lambertian albedo, or specular reflectance rho
  double exponent = 0.0;     // Phong exponent n
  double ior = 1.0;          // refractive index (glass)
  // Whitted mode: weights of the local Phong term's diffuse and specular parts. The
  // children then weigh 1 - diffuse - specular, so that a node's weights sum to 1.
  double whittedDiffuse = 0.0;
  double whittedSpecular = 0.0;

  bool IsTransparent() const { return type == MaterialType::Glass; }
  double WhittedChildWeight() const { return 1.0 - whittedDiffuse - whittedSpecular; }
};

}  // namespace glint
