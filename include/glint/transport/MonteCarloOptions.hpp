// The Monte Carlo mode's switches (the command line's --walls, --glass, --fresnel,
// --strategy, --branches, --mirror-light, --caustics,
// --simd), as MonteCarloIntegrator and its
// LightTracer read them.
#pragma once

#include "glint/core/SimdTarget.hpp"
#include "glint/transport/Fresnel.hpp"

namespace glint {

struct MonteCarloOptions {
  enum class Walls { Terminal, Diffuse };
  enum class Glass { Split, Choose };
  using Fresnel = FresnelModel;
  enum class Strategy { Mis, Light, Brdf };
  enum class MirrorLight { Nee, Brdf };
  enum class Caustics { Off, Light };

  Walls walls = Walls::Terminal;  // terminal: a wall hit spawns no child (the design)
  Glass glass = Glass::Split;     // split: reflect and refract; choose: one, by Fresnel
  Fresnel fresnel = Fresnel::Exact;
  Strategy strategy = Strategy::Mis;  // at Phong object hits
  int branches = 1;                   // children of a Phong object hit
  // With diffuse walls, the light seen in a mirror from a Lambertian point: next-event
  // estimation through the mirror (MirroredLight), or only the cosine-sampled rays that
  // happen to find it.
  MirrorLight mirrorLight = MirrorLight::Nee;
  // With diffuse walls, the caustics a wall seen by the camera receives through mirrors,
  // glass and Phong objects: found from the light's side as well (LightTracer), the two
  // strategies weighted by multiple importance sampling, or by the camera's paths alone.
  Caustics caustics = Caustics::Off;
  int maxDepth = 64;  // a safety cap; Russian roulette ends paths first
  // Russian roulette's threshold (MonteCarloIntegrator::kRouletteThreshold); tests set a
  // tiny one, which roulettes almost nothing, to show that roulette adds no bias.
  double rouletteThreshold = 0.25;
  // The instruction set of the lock-step lanes (--simd; TerminalWallLanes): any gives
  // the same image.
  SimdTarget simd = SimdTarget::Auto;
};

}  // namespace glint
