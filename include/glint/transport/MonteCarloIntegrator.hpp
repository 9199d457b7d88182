// Monte Carlo mode: the area light with next-event estimation, the normalised Phong
// BRDF with lobe sampling and multiple importance sampling, mirrors, Fresnel glass,
// Lambertian walls (terminal or diffuse), Russian roulette by throughput.
#pragma once

#include <optional>

#include "glint/camera/Integrator.hpp"
#include "glint/camera/Pinhole.hpp"
#include "glint/scene/Hit.hpp"
#include "glint/scene/Light.hpp"
#include "glint/scene/Material.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/CameraHitLanes.hpp"
#include "glint/transport/Fresnel.hpp"
#include "glint/transport/HitLanes.hpp"
#include "glint/transport/LambertianLightLanes.hpp"
#include "glint/transport/LambertianScatterLanes.hpp"
#include "glint/transport/LightTracer.hpp"
#include "glint/transport/MirroredLight.hpp"
#include "glint/transport/MonteCarloOptions.hpp"
#include "glint/transport/TerminalWallLanes.hpp"

namespace glint {

class MonteCarloIntegrator final : public Integrator {
 public:
  static constexpr int kMaxBranches = 64;
  // Russian roulette leaves paths whose throughput is at least this alone, and lets one
  // below it live with probability throughput / threshold. With 1 (every path rouletted
  // by its throughput) the glass sphere's light paths were most of the image's error: a
  // refraction out of the rim after internal reflections carries 1 - F << 1 toward the
  // light and was killed, or multiplied up, at random (see BENCHMARKS.md, "samplers").
  static constexpr double kRouletteThreshold = 0.25;  // MonteCarloOptions' default
  // With diffuse walls, a wall hit estimates the light seen in the mirrors with this
  // probability, and divides by it: the estimate costs more than the rest of the wall's
  // work (solving for the sphere's reflection point, two shadow segments per image) and
  // its variance is small beside that of the paths it replaces. At equal time (6.8 s,
  // the mirror scene at 256x256) relative MSE was 0.0123 at 0.02, 0.0117 at 0.05 and
  // 0.1, 0.0141 at 0.25, 0.0172 at 0.5, 0.0223 at 1, against 0.036 without it.
  static constexpr double kMirroredLightProbability = 0.1;

  // Throws std::invalid_argument if the scene has no area light, or if caustics by
  // light tracing are asked for without diffuse walls or without the camera they are
  // traced toward.
  MonteCarloIntegrator(const Scene& scene, MonteCarloOptions options,
                       std::optional<Pinhole> camera = std::nullopt);

  Colour Trace(RayTree& tree, std::uint32_t root, const PixelShaft& shaft, Sampler& sampler,
               RenderStats& stats) const override;
  PixelShaft::Lights ShadowLights() const override { return PixelShaft::Lights::Area; }
  // With terminal walls (and the camera given), a roomOnly pixel's rays run in lanes.
  int LaneWidth(const PixelShaft& shaft) const override {
    return lanes_ && shaft.roomOnly ? lanes_->Width() : 0;
  }
  SimdTarget LaneTarget() const override {
    if (lanes_) return lanes_->Target();
    return hitLanes_ ? hitLanes_->Target() : SimdTarget::Scalar;
  }
  void TraceLanes(RayLanes& lanes, int count, const PixelShaft& shaft,
                  RenderStats& stats) const override;
  // The camera rays that LaneWidth leaves find their first hit in lanes: with terminal
  // walls the other pixels', with diffuse walls every pixel's.
  bool FirstHitLanes(const PixelShaft& shaft, int rays) const override {
    return hitLanes_ && LaneWidth(shaft) == 0 && hitLanes_->Pays(rays);
  }
  void FindFirstHits(RayLanes& lanes, int count) const override { hitLanes_->Trace(lanes, count); }
  Colour TraceFromLane(RayTree& tree, std::uint32_t root, const PixelShaft& shaft,
                       const RayLanes& lanes, int lane, Sampler& sampler,
                       RenderStats& stats) const override;
  // And their paths in lock-step, up to 64 camera rays a group, each path still depth
  // first: 8 slots each trace one path, taking the group's next camera ray when theirs
  // ends; at every step each slot takes the next ray of its own depth-first order, and
  // those rays find their hits W at a time (HitLanes). Each path's nodes are numbered, and
  // its sample's numbers drawn, as TraceNode's recursion does them, so the trees and
  // colours are the same to the bit. With at most two children a node (the stack's bound).
  bool TracesGroupsFromLanes() const override {
    return secondaryLanes_.has_value() && options_.branches <= 2 &&
           options_.maxDepth <= kGroupStack;
  }
  int GroupRays() const override { return kMaxGroupRays; }
  void TraceGroupFromLanes(RayTree& trees, std::uint32_t firstRoot, int count,
                           const PixelShaft& shaft, const RayLanes* lanes, Sampler& sampler,
                           int firstSample, const Sampler::FirstGroups* groups, RenderStats& stats,
                           Colour* colours) const override;
  int LightPathsPerRay() const override { return tracer_ ? LightTracer::kPathsPerRay : 0; }
  void TraceLightPaths(Camera& camera, Sampler& sampler, int count,
                       RenderStats& stats) const override {
    if (tracer_) tracer_->Trace(camera, sampler, count, stats);
  }

  // Direct light at a surface point from one random point on the light (the sample's
  // numbers of dimension `dimension`): Le f cos(theta) / p(w), with f the BRDF for the
  // incident direction d.
  // `unoccluded`: the hit is known to see all of the light (PixelShaft::areaLightVisible),
  // so the shadow ray needs no test.
  // Defined in this header with the Lambertian case every wall hit takes and with
  // ShadowBlocked, so that the compiler has the walls' whole estimator in one piece: as
  // separate calls they passed their vectors through the stack, even for shadow rays
  // the shaft had answered (measured: 3%). The Phong case is a call.
  // `causticRatio`: the incident ray's Ray::causticRatio (light tracing's weight at a
  // Phong hit).
  Colour DirectLight(const Hit& hit, vec3 d, vec3 n, double misBranches, Sample2 uv,
                     RenderStats& stats, bool unoccluded = false, double causticRatio = 0.0) const {
    if (hit.material->type == MaterialType::Lambertian) {
      return DirectLightLambertian(hit, n, uv.u, uv.v, stats, unoccluded);
    }
    return DirectLightPhong(hit, d, n, misBranches, uv.u, uv.v, stats, unoccluded, causticRatio);
  }

  const MonteCarloOptions& Options() const { return options_; }

 private:
  // DirectLight at a Lambertian surface, for the light point of the random numbers u, v.
  Colour DirectLightLambertian(const Hit& hit, vec3 n, double u, double v, RenderStats& stats,
                               bool unoccluded) const;
  // DirectLight at a Phong surface (with MIS against `misBranches` BRDF samples).
  Colour DirectLightPhong(const Hit& hit, vec3 d, vec3 n, double misBranches, double u, double v,
                          RenderStats& stats, bool unoccluded, double causticRatio) const;

  // Counts the shadow ray from surface point p (normal n, toward w) to the light point y
  // and says whether an object blocks it; one the pixel's shaft answered (`unoccluded`)
  // is not tested.
  bool ShadowBlocked(vec3 p, vec3 n, vec3 w, vec3 y, bool unoccluded, RenderStats& stats) const {
    ++stats.shadowRays;
    if (unoccluded) {
      ++stats.shadowRaysByShaft;  // answered by the pixel's shaft: nothing can block it
      return false;
    }
    return scene_.Occluded(OffsetRayOrigin(p, n, w), y);
  }

  // No default member initializers, so that an array of them is left uninitialised: Scatter
  // writes each candidate it returns whole (Of). Zeroing TraceNode's 64 took 6% of a
  // render with diffuse walls (measured).
  struct Candidate {
    vec3 direction;
    Colour weight;
    double pdf;
    RayKind kind;
    bool inside;
    bool lightCounted;    // Ray::lightCounted
    double causticRatio;  // Ray::causticRatio
    static Candidate Of(vec3 direction, Colour weight, double pdf, RayKind kind, bool inside,
                        bool lightCounted = false) {
      return {direction, weight, pdf, kind, inside, lightCounted, 0.0};
    }
  };

  // The end of a ray that hit a terminal wall (`hit`, normal n facing the ray): its colour
  // is the wall's direct light, it spawns no child. Sets the node's colour and final flag.
  // `node`: the ray's node number in its tree (SampleDimension).
  Colour EndAtTerminalWall(Ray& ray, const Hit& hit, vec3 n, std::uint32_t node, Sampler& sampler,
                           RenderStats& stats, bool unoccluded) const;

  // The rays a lock-step slot has still to trace: with at most two children a node, one
  // sibling waiting at each depth 1 .. maxDepth - 2 and two at the deepest, maxDepth at most.
  static constexpr int kGroupStack = 64;

  // `shaft`: what is known in advance of this ray (the camera ray's pixel), or nothing;
  // `known`: its hit, found already (CameraHitLanes; t infinite: it met nothing), or null.
  Colour TraceNode(RayTree& tree, std::uint32_t index, std::uint32_t root, Sampler& sampler,
                   RenderStats& stats, PixelShaft shaft = {}, const Hit* known = nullptr) const;
  // The hit of `ray`, as TraceNode finds it without a known hit.
  void FindHit(const Ray& ray, const PixelShaft& shaft, Hit& hit) const;
  // What TraceNode does at tree[index] (node `node` of the tree whose root is tree[root])
  // once its hit is known, but for its children's colours: its end, object and final
  // flag, its local light into `local` (and into its colour), its children after Russian
  // roulette (from tree[index].firstChild); returns how many it kept.
  // What a lock-step group leaves to lanes at its Lambertian hits, their numbers drawn in
  // ShadeNode's order all the same.
  struct WallLaneWork {
    LambertianLightLaneData lights;      // the next-event estimates
    LambertianScatterLaneData children;  // the cosine-sampled children's rays
  };
  // `deferred`: if given, a Lambertian hit's next-event estimate and its child's ray are
  // left to the lanes: the node's and `local`'s colour lack the estimate until
  // FlushWallLights adds it, and the child has no start or direction until
  // FlushWallChildren.
  std::uint32_t ShadeNode(RayTree& tree, std::uint32_t index, std::uint32_t node,
                          std::uint32_t root, const Hit& hit, Colour& local, Sampler& sampler,
                          RenderStats& stats, const PixelShaft& shaft,
                          WallLaneWork* deferred = nullptr) const;
  // The deferred estimates, in lanes: each added to its node's colour (the estimate first,
  // as ShadeNode's sum has it), its shadow ray counted.
  void FlushWallLights(RayTree& trees, LambertianLightLaneData& deferred, RenderStats& stats) const;
  // The deferred children's rays, in lanes: their start and direction set.
  void FlushWallChildren(RayTree& trees, LambertianScatterLaneData& deferred) const;
  // How much of the light's emission a ray that hit it counts: 1, an MIS weight, or 0
  // where next-event estimation has counted it already.
  double EmissionWeight(const Ray& ray, vec3 lightPoint) const;
  // Candidate children of a hit of node `node` (before Russian roulette); returns their
  // number. `deferred`: if given, a Lambertian hit's child direction is left to the lanes
  // (staged there; the candidate's direction is 0).
  int Scatter(const Ray& ray, const Hit& hit, vec3 n, std::uint32_t node, Sampler& sampler,
              Candidate* out, LambertianScatterLaneData* deferred = nullptr) const;
  // With light tracing: the candidates' Ray::causticRatio, from the ray's.
  void SetCausticRatios(const Ray& ray, const Hit& hit, vec3 n, Candidate* candidates,
                        int count) const;

  const Scene& scene_;
  const Light& light_;
  MonteCarloOptions options_;
  MirroredLight mirrored_;
  bool useMirrored_;                   // diffuse walls, MirrorLight::Nee, and mirrors in the scene
  std::optional<LightTracer> tracer_;  // Caustics::Light
  std::optional<TerminalWallLanes> lanes_;                // Walls::Terminal, with the camera
  std::optional<CameraHitLanes> hitLanes_;                // with the camera
  std::optional<HitLanes> secondaryLanes_;                // with the camera, from 4 lanes
  std::optional<LambertianLightLanes> wallLightLanes_;    // with secondaryLanes_
  std::optional<LambertianScatterLanes> wallChildLanes_;  // with secondaryLanes_
};

// Inline: the walls' hits, most of a render, take this path.
inline Colour MonteCarloIntegrator::DirectLightLambertian(const Hit& hit, vec3 n, double u,
                                                          double v, RenderStats& stats,
                                                          bool unoccluded) const {
  // The same estimator as DirectLightPhong's, Le f cos(theta) / p(w) with p(w) = r^2 /
  // (cos(theta_y) A), for the BRDF rho / pi that needs no direction: with x = y - p
  // unnormalised, cos(theta) = n.x / r and cos(theta_y) = -n_y.x / r, so
  //   Le (rho / pi) (n.x) (-n_y.x) A / r^4      -- no square root, one division.
  const vec3 y = light_.SamplePoint(u, v);
  const vec3 x = y - hit.point;
  const double cosNumerator = glm::dot(n, x);
  const double cosLightNumerator = -glm::dot(light_.Normal(), x);
  if (cosNumerator <= 0.0 || cosLightNumerator <= 0.0) return Colour(0.0);
  if (ShadowBlocked(hit.point, n, x, y, unoccluded, stats)) return Colour(0.0);
  const double r2 = glm::dot(x, x);
  const double geometry = cosNumerator * cosLightNumerator * light_.Area() / (r2 * r2);
  return light_.Radiance() * hit.material->reflectance * (kInvPi * geometry);
}

}  // namespace glint
