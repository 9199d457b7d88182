// Light tracing, the t = 1 strategy of bidirectional path tracing (Veach 1997, ch. 10;
// pbrt-v4's LightPathIntegrator): the Monte Carlo mode's caustics found from the light's
// side (--caustics light, diffuse walls). A light path starts at a uniform point y of the
// area light (density 1/A) in a cosine-distributed direction (cos / pi), so that it
// carries beta = Le cos / (p_A p_w) = Le A pi; it goes on through mirrors, glass (split or
// chosen by Fresnel, as --glass says), Phong objects (their lobe sampled) and, once it has
// met one of those, Lambertian surfaces (cosine-sampled), with Russian roulette as a
// camera path has. At every Lambertian surface x it lands on after an object, x is joined
// to the eye, and if nothing stands between them the pixel x is seen in receives
//   beta (rho / pi) W_e(x) w / (lambda P)                   (Pinhole::Importance)
// as a splat, lambda P light paths being traced per camera ray of each of the P pixels.
// Paths whose first object is one mirror and which then land on a wall are MirroredLight's
// (next-event estimation through the mirror) and are not followed.
//
// The same paths eye -> x -> ... -> object -> light are found by the camera's path too:
// x's cosine-sampled ray goes on through the same surfaces to the light (s = 0), or, if
// the object next to the light is Phong, next-event estimation there (s = 1). Each
// counts with the power heuristic's weight (Veach eq. 9.13) among those that apply, so
// that every path is counted once. The densities of a path under the strategies share
// every factor but a few (all in projected solid angle: mirror and glass vertices are the
// same deltas both ways, the cosine densities of a Lambertian vertex are 1 / pi both ways,
// and the geometry terms of every edge appear in each):
//   r = p_t1 / p_s0 = lambda P / (A W_e(x)) * prod over Phong vertices of
//       cos(theta toward the light) / (branches cos(theta toward the eye)),
// the pixel's W_e(x) being the density, per unit area, of its camera ray's hit at x
// against the light point's 1 / A. The camera side keeps r in each ray
// (Ray::causticRatio) and weighs its light hit 1 / (1 + r^2 [+ r_s1^2]); here the weight
// is 1 / (1 + 1/r^2 [+ (p_s1 / p_t1)^2]).
#pragma once

#include <optional>

#include "glint/camera/Pinhole.hpp"
#include "glint/camera/RenderStats.hpp"
#include "glint/core/Math.hpp"
#include "glint/sampling/Sampler.hpp"
#include "glint/scene/Hit.hpp"
#include "glint/scene/Light.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/MonteCarloOptions.hpp"

namespace glint {

class Camera;

class LightTracer {
 public:
  // Light paths per camera ray (lambda): one light path costs about one ray, most of
  // them ending on a wall without meeting an object.
  static constexpr int kPathsPerRay = 1;

  // Which landings are joined to the eye: the caustic paths above (weighted against the
  // camera's), or, to check W_e against a closed form, only the light's first landing on a
  // Lambertian surface, weight 1: light tracing then estimates alone what next-event
  // estimation does at the surfaces the camera sees (terminal walls' image).
  enum class Joins { Caustics, Direct };
  // `joinSingleMirror`: also join paths that met one mirror only (MirroredLight off).
  LightTracer(const Scene& scene, const Light& light, const MonteCarloOptions& options,
              const Pinhole& camera, bool joinSingleMirror, Joins joins = Joins::Caustics);

  // Traces `count` light paths, the sampler's samples 0 .. count - 1, splatting into
  // `camera`'s pixels.
  void Trace(Camera& camera, Sampler& sampler, int count, RenderStats& stats) const;

  // The camera side's r at the first hit x (normal n toward the eye) of a camera ray:
  // lambda P / (A W_e(x)), 0 where x is outside the image (then the camera counts alone).
  double CameraRatio(vec3 x, vec3 n) const {
    const double we = camera_.Importance(x, n).we;
    return we > 0.0 ? scale_ / (light_.Area() * we) : 0.0;
  }
  // What a Phong vertex multiplies r by, for the direction toward the light (cosine
  // cosLight to the normal) and toward the eye (cosEye), with `branches` samples there.
  static double PhongFactor(double cosLight, double cosEye, int branches) {
    return cosLight / (static_cast<double>(branches) * cosEye);
  }

 private:
  // A light path between two surfaces: where it starts, where it goes, what it carries,
  // and what its multiple-importance weight needs.
  struct PathState {
    vec3 origin;
    vec3 direction;
    Colour beta;
    bool inside = false;
    int interior = 0;           // surfaces met (the path's vertices between light and eye)
    int vertices = 0;           // of them, mirror, glass and Phong vertices
    int mirrors = 0;            // of them, mirrors
    bool firstIsPhong = false;  // the vertex next to the light is Phong
    // p_s0 / p_t1 and p_s1 / p_t1 without the factor W_e(x) / (lambda P) they share at
    // the landing point: A prod(branches cos_eye / cos_light) and, where the vertex next
    // to the light is Phong with next-event estimation, 1 / (G p_sigma) there times the
    // later Phong vertices' factors.
    double s0 = 1.0;
    double s1 = 0.0;
  };
  void Follow(Camera& camera, Sampler& sampler, PathState path, std::uint32_t& node, Colour beta0,
              RenderStats& stats) const;
  // Adds the landing point's splat (x = hit.point, n toward where the path came from).
  void Join(Camera& camera, const Hit& hit, vec3 n, const PathState& path,
            RenderStats& stats) const;
  // Russian roulette of a continuation whose throughput is beta (relative to beta0):
  // false if it ends; else beta is divided by its survival probability.
  bool Survives(Colour& beta, Colour beta0, Sampler& sampler, std::uint32_t dimension) const;

  const Scene& scene_;
  const Light& light_;
  MonteCarloOptions options_;
  Pinhole camera_;
  bool joinSingleMirror_;
  Joins joins_;
  double scale_;  // lambda P
};

}  // namespace glint
