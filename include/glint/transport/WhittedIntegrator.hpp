// Whitted mode: point lights, shadow rays through transparent objects, the Phong local
// term on objects, Lambertian walls lit directly, perfect mirror reflection and
// Fresnel-weighted reflection and refraction, at most `maxDepth` ray iterations.
#pragma once

#include "glint/camera/Integrator.hpp"
#include "glint/scene/Hit.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/Fresnel.hpp"

namespace glint {

class WhittedIntegrator final : public Integrator {
 public:
  // `fresnel`: the glass's reflectance, the Fresnel equations or the small-angle
  // approximation (the normal-incidence reflectance at every angle).
  WhittedIntegrator(const Scene& scene, int maxDepth, FresnelModel fresnel = FresnelModel::Exact);

  Colour Trace(RayTree& tree, std::uint32_t root, const PixelShaft& shaft, Sampler& sampler,
               RenderStats& stats) const override;
  PixelShaft::Lights ShadowLights() const override { return PixelShaft::Lights::Point; }

  // The local term at a hit seen along direction d: for every visible point light of
  // intensity I at distance r and angle theta, with E = I cos(theta) / r^2,
  //   rho * E * (kd / pi + ks (n + 2) / (2 pi) max(0, R . -d)^n),
  // R being the light's mirror direction. For a wall (kd = 1, ks = 0) this is the
  // spec's rho / pi * I cos(theta) / r^2.
  // A point light the hit's pixel shaft sees (PixelShaft::PointLightVisible) is taken
  // as visible without a shadow ray.
  Colour LocalLight(const Hit& hit, vec3 d, RenderStats& stats, PixelShaft shaft = {}) const;

 private:
  // `shaft`: what is known in advance of this ray (the camera ray's pixel), or nothing.
  Colour TraceNode(RayTree& tree, std::uint32_t index, RenderStats& stats,
                   PixelShaft shaft = {}) const;
  // Creates the reflected and refracted children of tree[index] for its hit and
  // returns how many it made.
  std::uint32_t SpawnChildren(RayTree& tree, std::uint32_t index, const Hit& hit,
                              RenderStats& stats) const;

  const Scene& scene_;
  int maxDepth_;
  FresnelModel fresnel_;
};

}  // namespace glint
