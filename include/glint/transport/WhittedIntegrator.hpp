// Whitted mode: point lights, shadow rays through transparent objects, the Phong local
// term on objects, Lambertian walls lit directly, perfect mirror reflection and
// Fresnel-weighted reflection and refraction, at most `maxDepth` ray iterations.
#pragma once

#include <optional>

#include "glint/camera/Integrator.hpp"
#include "glint/camera/Pinhole.hpp"
#include "glint/scene/Hit.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/CameraHitLanes.hpp"
#include "glint/transport/Fresnel.hpp"
#include "glint/transport/HitLanes.hpp"
#include "glint/transport/LocalLightLanes.hpp"
#include "glint/transport/SpecularLanes.hpp"
#include "glint/transport/WhittedWallLanes.hpp"

namespace glint {

class WhittedIntegrator final : public Integrator {
 public:
  // `fresnel`: the glass's reflectance, the Fresnel equations or the small-angle
  // approximation (the normal-incidence reflectance at every angle). With the `camera`
  // the pixels shoot from, a roomOnly pixel's camera rays run in SIMD lanes on `simd`
  // (WhittedWallLanes; the same image). Throws std::invalid_argument for a target the
  // CPU lacks.
  WhittedIntegrator(const Scene& scene, int maxDepth, FresnelModel fresnel = FresnelModel::Exact,
                    std::optional<Pinhole> camera = std::nullopt,
                    SimdTarget simd = SimdTarget::Auto);

  Colour Trace(RayTree& tree, std::uint32_t root, const PixelShaft& shaft, Sampler& sampler,
               RenderStats& stats) const override;
  PixelShaft::Lights ShadowLights() const override { return PixelShaft::Lights::Point; }
  // A roomOnly pixel whose wall has no specular lobe runs in lanes (with the camera).
  int LaneWidth(const PixelShaft& shaft) const override;
  SimdTarget LaneTarget() const override { return lanes_ ? lanes_->Target() : SimdTarget::Scalar; }
  bool LanesTakeLightPoint() const override { return false; }  // point lights: no numbers
  void TraceLanes(RayLanes& lanes, int count, const PixelShaft& shaft,
                  RenderStats& stats) const override;
  // The other pixels' camera rays find their first hit in lanes too, from 4 rays a pixel
  // (Whitted's default; their trees then run a level at a time).
  bool FirstHitLanes(const PixelShaft& shaft, int rays) const override {
    return hitLanes_ && LaneWidth(shaft) == 0 && hitLanes_->PaysFrom(rays, 4);
  }
  void FindFirstHits(RayLanes& lanes, int count) const override { hitLanes_->Trace(lanes, count); }
  Colour TraceFromLane(RayTree& tree, std::uint32_t root, const PixelShaft& shaft,
                       const RayLanes& lanes, int lane, Sampler& sampler,
                       RenderStats& stats) const override;
  // And their trees breadth-first, up to 64 camera rays' at once, a level at a time, each
  // level's hits in lanes (HitLanes): the same trees and colours as TraceNode's
  // depth-first recursion.
  bool TracesGroupsFromLanes() const override { return secondaryLanes_.has_value(); }
  int GroupRays() const override { return kMaxGroupRays; }
  // (Whitted draws no numbers after the pixel point: the sampler is not used.)
  void TraceGroupFromLanes(RayTree& trees, std::uint32_t firstRoot, int count,
                           const PixelShaft& shaft, const RayLanes* lanes, Sampler& sampler,
                           int firstSample, const Sampler::FirstGroups* groups, RenderStats& stats,
                           Colour* colours) const override;

  // The local term at a hit seen along direction d: for every visible point light of
  // intensity I at distance r and angle theta, with E = I cos(theta) / r^2,
  //   rho * E * (kd / pi + ks (n + 2) / (2 pi) max(0, R . -d)^n),
  // R being the light's mirror direction. For a wall (kd = 1, ks = 0) this is the
  // spec's rho / pi * I cos(theta) / r^2.
  // A point light the hit's pixel shaft sees (PixelShaft::PointLightVisible) is taken
  // as visible without a shadow ray.
  Colour LocalLight(const Hit& hit, vec3 d, RenderStats& stats, PixelShaft shaft = {}) const;

 private:
  // `shaft`: what is known in advance of this ray (the camera ray's pixel), or nothing;
  // `known`: its hit, found already (CameraHitLanes; t infinite: it met nothing), or null.
  Colour TraceNode(RayTree& tree, std::uint32_t index, RenderStats& stats, PixelShaft shaft = {},
                   const Hit* known = nullptr) const;
  // The hit of tree[index]'s ray, as TraceNode finds it without a known hit.
  void FindHit(const RayTree& tree, std::uint32_t index, const PixelShaft& shaft, Hit& hit) const;
  // What TraceNode does at tree[index] once its hit is known, but for its children's
  // colours: its end, object and final flag, its local light into `local` (and, with no
  // children, its colour), its children; returns how many it made. `knownLocal`: its
  // local light, found already (LocalLightLanes), or null; `known`: its children's
  // directions, found already in lane `lane` (SpecularLanes), or null.
  std::uint32_t ShadeNode(RayTree& tree, std::uint32_t index, const Hit& hit, Colour& local,
                          RenderStats& stats, const PixelShaft& shaft,
                          const Colour* knownLocal = nullptr,
                          const SpecularLaneData* known = nullptr, std::size_t lane = 0) const;
  // Shades tree[first, first + n), whose hits are hits[0, n), as ShadeNode does, their
  // local terms and children's directions in lanes (LocalLightLanes, SpecularLanes), with
  // `lights` and `specular` as the lanes' storage.
  void ShadeBatch(RayTree& trees, std::uint32_t first, int n, const Hit* hits,
                  const PixelShaft& shaft, LocalLightLaneData& lights, SpecularLaneData& specular,
                  RenderStats& stats) const;
  // Creates the reflected and refracted children of tree[index] for its hit and
  // returns how many it made; `known`, `lane`: as for ShadeNode.
  std::uint32_t SpawnChildren(RayTree& tree, std::uint32_t index, const Hit& hit,
                              RenderStats& stats, const SpecularLaneData* known = nullptr,
                              std::size_t lane = 0) const;
  // Point light i, at cos(theta) > 0 from p (normal n facing the ray): counts its
  // shadow ray and says whether the light reaches p (the shaft's answer, or a shadow
  // ray through transparent objects).
  bool Reaches(std::size_t i, vec3 p, vec3 n, const PixelShaft& shaft, RenderStats& stats) const;

  const Scene& scene_;
  int maxDepth_;
  FresnelModel fresnel_;
  std::optional<WhittedWallLanes> lanes_;       // with the camera
  std::optional<CameraHitLanes> hitLanes_;      // the same
  std::optional<HitLanes> secondaryLanes_;      // the same
  std::optional<LocalLightLanes> localLights_;  // the same
  std::optional<SpecularLanes> specularLanes_;  // the same
};

}  // namespace glint
