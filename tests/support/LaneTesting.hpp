// What the SIMD lanes' tests share: bit-for-bit comparison of doubles, vectors, images
// and a pixel's ray trees, and a small render with a given integrator.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "glint/camera/Camera.hpp"
#include "glint/image/Image.hpp"
#include "glint/sampling/Rng.hpp"
#include "glint/scene/Scene.hpp"

namespace glint::testing {

// The same bits (a NaN equals itself here, and 0.0 differs from -0.0).
inline bool SameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
inline bool SameBits(vec3 a, vec3 b) {
  return SameBits(a.x, b.x) && SameBits(a.y, b.y) && SameBits(a.z, b.z);
}
inline int DifferingPixels(const Image& a, const Image& b) {
  int differing = 0;
  for (std::size_t i = 0; i < a.Pixels().size(); ++i) {
    differing += !SameBits(a.Pixels()[i], b.Pixels()[i]);
  }
  return differing;
}

// A ray from a uniform point of `scene`'s room in a uniform direction (the lanes' tests'
// hits: every wall, object and side of them).
struct RoomRay {
  vec3 origin, direction;
};
inline RoomRay RandomRoomRay(const Scene& scene, Pcg32& rng) {
  const vec3 lo = scene.wall.Position();
  const vec3 o =
      lo + vec3(rng.Uniform(), rng.Uniform(), rng.Uniform()) * (scene.wall.MaxCorner() - lo);
  const double z = 2.0 * rng.Uniform() - 1.0;
  const double phi = 2.0 * kPi * rng.Uniform();
  const double s = std::sqrt(1.0 - z * z);
  return {o, vec3(s * std::cos(phi), s * std::sin(phi), z)};
}

struct LaneRender {
  Image image;
  RenderStats stats;
};

// A width x height render of `spp` rays per pixel, seed 5, one thread, shafts prepared.
inline LaneRender RenderWith(const Scene& scene, const Integrator& integrator, SamplerKind sampler,
                             int spp, int width, int height) {
  Camera camera(scene.wall, scene.camera, width, height);
  camera.PrepareShafts(scene, integrator.ShadowLights(), 1);
  RenderOptions options;
  options.raysPerPixel = spp;
  options.seed = 5;
  options.sampler = sampler;
  options.threads = 1;
  LaneRender r{Image(1, 1), camera.Render(integrator, options)};
  r.image = camera.ToImage();
  return r;
}

// Every node of two ray trees, to the bit.
inline void ExpectSameTrees(const RayTree& a, const RayTree& b) {
  ASSERT_EQ(a.Size(), b.Size());
  for (std::uint32_t i = 0; i < a.Size(); ++i) {
    EXPECT_TRUE(SameBits(a[i].start, b[i].start));
    EXPECT_TRUE(SameBits(a[i].direction, b[i].direction));
    EXPECT_TRUE(SameBits(a[i].end, b[i].end));
    EXPECT_TRUE(SameBits(a[i].colour, b[i].colour));
    EXPECT_TRUE(SameBits(a[i].weight, b[i].weight));
    EXPECT_TRUE(SameBits(a[i].importance, b[i].importance));
    EXPECT_EQ(a[i].object, b[i].object);
    EXPECT_EQ(a[i].final, b[i].final);
    EXPECT_EQ(a[i].kind, b[i].kind);
    EXPECT_EQ(a[i].childCount, b[i].childCount);
  }
}

}  // namespace glint::testing
