// Next-event estimation of the area light seen in the scene's perfect mirrors: the
// light that reaches a Lambertian point x by one reflection off a mirror cube's face or
// a mirror sphere. With diffuse walls these caustics are otherwise found only when a
// cosine-sampled ray happens to hit the mirror at the angle that shows the light: in
// the mirror scene they held two thirds of the image's relative MSE (BENCHMARKS.md,
// "The light seen in mirrors").
//
// One light point y (uniform, density 1/A) serves every mirror: the path x -> m -> y is
// y's mirror image seen through a plane face (the face's point m on the segment from x
// to the image), or the reflection point of x and y on a sphere (SphereReflection.hpp).
// Each mirror adds
//   rho Le cos(theta_x) cos(theta_y) A / spread     if x -> m and m -> y are unblocked,
// with spread = |x - image|^2 for a plane, and the sphere's beam spread. A ray that
// leaves x and reaches the light by one such reflection then counts no emission (the
// integrator's EmissionWeight): every such path is counted once, here.
#pragma once

#include <vector>

#include "glint/camera/RenderStats.hpp"
#include "glint/core/Math.hpp"
#include "glint/scene/Light.hpp"
#include "glint/scene/Rectangle.hpp"

namespace glint {

class Scene;

class MirroredLight {
 public:
  // The mirror faces of the scene's cubes that some point of the light lies in front
  // of, and the mirror spheres.
  MirroredLight(const Scene& scene, const Light& light);

  bool Empty() const { return planes_.empty() && spheres_.empty(); }

  // Irradiance at x (unit normal n, on the side light arrives from) from the light's
  // images in the mirrors, estimated with the light point of the numbers u, v. Counts
  // each shadow segment it tests (two per image: x to the mirror, the mirror to y).
  Colour Irradiance(vec3 x, vec3 n, double u, double v, RenderStats& stats) const;

 private:
  struct PlaneMirror {
    Rectangle face;
    Colour rho;
    vec3 imageNormal;  // the emitting side of the light's mirror image
  };
  struct SphereMirror {
    vec3 centre;
    double radius;
    Colour rho;
  };

  // Whether an object blocks x -> m or m -> y (m on a mirror with outward normal mn).
  bool Blocked(vec3 x, vec3 n, vec3 m, vec3 mn, vec3 y, RenderStats& stats) const;

  const Scene& scene_;
  const Light& light_;
  std::vector<PlaneMirror> planes_;
  std::vector<SphereMirror> spheres_;
};

}  // namespace glint
