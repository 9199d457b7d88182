// Helpers shared by the Monte Carlo tests: Lambert's closed form for the light, and
// block means of independent renders for comparing estimators within error bars.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/Statistics.hpp"

namespace glint::testing {

// Integral of cos(theta) over the solid angle of a polygon seen from p with normal n
// (Lambert): 1/2 sum_i angle(u_i, u_i+1) n . normalize(u_i x u_i+1).
inline double PolygonCosineIntegral(vec3 p, vec3 n, const std::vector<vec3>& vertices) {
  double sum = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const vec3 a = glm::normalize(vertices[i] - p);
    const vec3 b = glm::normalize(vertices[(i + 1) % vertices.size()] - p);
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) *
           glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * std::abs(sum);
}

// One render of a small square image with the sampler `kind` (no NaN or Inf sample).
inline Image RenderWithSampler(const Scene& scene, const Integrator& integrator, SamplerKind kind,
                               int size, int spp, std::uint64_t seed, int threads = 0) {
  Camera camera(scene.wall, scene.camera.eye, size, size);
  RenderOptions options;
  options.sampler = kind;
  options.raysPerPixel = spp;
  options.seed = seed;
  options.threads = threads;
  const RenderStats stats = camera.Render(integrator, options);
  EXPECT_EQ(stats.nonFiniteSamples, 0U);
  return camera.ToImage();
}

// Block means of `runs` independent renders (different seeds) of a small image.
struct BlockEstimates {
  std::vector<MeanAndError> blocks;  // block-major, 3 channels each
};

inline BlockEstimates RenderBlocks(const Scene& scene, MonteCarloOptions options, int size,
                                   int block, int spp, int runs, std::uint64_t seedBase) {
  const MonteCarloIntegrator integrator(scene, options);
  const int nb = size / block;
  BlockEstimates out;
  out.blocks.resize(static_cast<std::size_t>(nb * nb * 3));
  for (int r = 0; r < runs; ++r) {
    Camera camera(scene.wall, scene.camera.eye, size, size);
    RenderOptions ro;
    ro.raysPerPixel = spp;
    ro.seed = seedBase + static_cast<std::uint64_t>(r);
    const RenderStats stats = camera.Render(integrator, ro);
    EXPECT_EQ(stats.nonFiniteSamples, 0u);
    for (int by = 0; by < nb; ++by) {
      for (int bx = 0; bx < nb; ++bx) {
        Colour sum(0.0);
        for (int y = by * block; y < (by + 1) * block; ++y) {
          for (int x = bx * block; x < (bx + 1) * block; ++x)
            sum += camera.PixelAt(x, y).Radiance();
        }
        for (int k = 0; k < 3; ++k) {
          out.blocks[static_cast<std::size_t>((by * nb + bx) * 3 + k)].Add(sum[k] /
                                                                           (block * block));
        }
      }
    }
  }
  return out;
}

}  // namespace glint::testing
