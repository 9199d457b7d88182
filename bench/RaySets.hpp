// Realistic ray distributions for the micro-benchmarks, drawn from the canonical scene:
// camera rays through random points of a 256x256 image, bounce rays leaving the first
// hits in cosine-distributed directions, and shadow rays from the first hits toward
// random points on the area light.
#pragma once

#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/sampling/Sampling.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/scene/SceneLoader.hpp"

namespace glint::bench {

struct RaySet {
  std::vector<vec3> origins;
  std::vector<vec3> directions;
  std::vector<double> tMax;  // the segment's length for shadow rays, kInfinity otherwise
  std::vector<vec3> ends;    // shadow rays: the point on the light

  std::size_t Size() const { return origins.size(); }
  void Add(vec3 o, vec3 d, double t, vec3 end = vec3(0.0)) {
    origins.push_back(o);
    directions.push_back(d);
    tMax.push_back(t);
    ends.push_back(end);
  }
};

inline constexpr int kRays = 4096;  // a set fits in L2: the benchmarks measure arithmetic

inline const Scene& CanonicalScene() {
  static const Scene scene = LoadScene(std::string(GLINT_SOURCE_DIR) + "/scenes/cornell.json");
  return scene;
}

inline RaySet CameraRays(const Scene& scene, int count = kRays) {
  const Camera camera(scene.wall, scene.camera, 256, 256);
  Pcg32 rng(7, 1);
  RaySet set;
  for (int i = 0; i < count; ++i) {
    const double px = 256.0 * rng.Uniform();
    const double py = 256.0 * rng.Uniform();
    set.Add(camera.Eye(), camera.DirectionThrough(px, py), kInfinity);
  }
  return set;
}

// Rays drawn from the first hits of camera rays (the light excluded): for each hit,
// `spawn(point, n, rng, set)` adds at most one ray; n faces the side the camera came from.
template <typename Spawn>
RaySet FromFirstHits(const Scene& scene, int count, std::uint64_t stream, Spawn spawn) {
  const RaySet camera = CameraRays(scene, 4 * count);
  Pcg32 rng(7, stream);
  RaySet set;
  for (std::size_t i = 0; i < camera.Size() && static_cast<int>(set.Size()) < count; ++i) {
    Hit hit;
    if (!scene.Intersect(camera.origins[i], camera.directions[i], hit, true) || hit.light) continue;
    const vec3 n = FacingNormal(camera.directions[i], hit.normal);
    spawn(hit.point, n, rng, set);
  }
  return set;
}

// Cosine-distributed about the normal: the walls' rays of `--walls diffuse`.
inline RaySet BounceRays(const Scene& scene, int count = kRays) {
  return FromFirstHits(scene, count, 2, [](vec3 p, vec3 n, Pcg32& rng, RaySet& set) {
    const vec3 w = glm::normalize(
        Frame::FromZ(n).ToWorld(SampleCosineHemisphere(rng.Uniform(), rng.Uniform())));
    set.Add(OffsetRayOrigin(p, n, w), w, kInfinity);
  });
}

// Next-event estimation's shadow rays: to random points on the light.
inline RaySet ShadowRays(const Scene& scene, int count = kRays) {
  return FromFirstHits(scene, count, 3, [&](vec3 p, vec3 n, Pcg32& rng, RaySet& set) {
    const LightSample ls = scene.light->SampleLi(p, rng.Uniform(), rng.Uniform());
    if (ls.pdf == 0.0) return;
    const vec3 o = OffsetRayOrigin(p, n, ls.wi);
    set.Add(o, ls.wi, glm::length(ls.point - o), ls.point);
  });
}

}  // namespace glint::bench
