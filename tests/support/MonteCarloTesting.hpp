// Helpers shared by the Monte Carlo tests: Lambert's closed form for the light, and
// block means of independent renders for comparing estimators within error bars.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "support/Power.hpp"
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

// One render of a small square image with the sampler `kind` (no NaN or Inf sample), on
// the path `glint render` takes: the pixels' shafts prepared (PixelShaft), one pass.
inline Image RenderWithSampler(const Scene& scene, const Integrator& integrator, SamplerKind kind,
                               int size, int spp, std::uint64_t seed, int threads = 0) {
  Camera camera(scene.wall, scene.camera, size, size);
  camera.PrepareShafts(scene, integrator.ShadowLights(), threads);
  RenderOptions options;
  options.sampler = kind;
  options.raysPerPixel = spp;
  options.seed = seed;
  options.threads = threads;
  const RenderStats stats = camera.Render(integrator, options);
  EXPECT_EQ(stats.nonFiniteSamples, 0U);
  return camera.ToImage();
}

// Block means of `runs` independent renders (different seeds; by default glint render's
// sampler, sobol, whose scrambling is independent from seed to seed) of a small image, and each
// channel's whole-image mean of every run, each pixel weighted by PilotWeights
// (support/Power.hpp: a relative mean that the light's edge does not swamp). The pilot
// is a render independent of the runs, so the weights are fixed.
struct BlockEstimates {
  std::vector<MeanAndError> blocks;  // block-major, 3 channels each
  MeanAndError whole[3];
};

inline BlockEstimates RenderBlocks(const Scene& scene, MonteCarloOptions options, int size,
                                   int block, int spp, int runs, std::uint64_t seedBase,
                                   const Image& pilot, SamplerKind sampler = SamplerKind::Sobol) {
  const MonteCarloIntegrator integrator(scene, options);
  const int nb = size / block;
  BlockEstimates out;
  out.blocks.resize(static_cast<std::size_t>(nb * nb * 3));
  Camera camera(scene.wall, scene.camera, size, size);
  camera.PrepareShafts(scene, integrator.ShadowLights());  // as glint render does
  const Image pixelWeights = PilotWeights(pilot);
  for (int r = 0; r < runs; ++r) {
    camera.Clear();
    RenderOptions ro;
    ro.raysPerPixel = spp;
    ro.seed = seedBase + static_cast<std::uint64_t>(r);
    ro.sampler = sampler;
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
    for (int k = 0; k < 3; ++k) {
      double weighted = 0.0;
      double weights = 0.0;
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          const double w = pixelWeights.At(x, y)[k];
          weighted += w * camera.PixelAt(x, y).Radiance()[k];
          weights += w;
        }
      }
      out.whole[k].Add(weighted / weights);
    }
  }
  return out;
}

// Do the block estimates of two estimators agree? Each block and channel by Welch's t
// against Student's t quantile at the Sidak-corrected level of `familyAlpha` over all of
// them (few runs: normal quantiles would understate the tails), and each channel's
// weighted whole-image mean by Welch's t at level 1e-4 (three of them: 3e-4). Family
// false-alarm rate of one call: familyAlpha + 3e-4. `scale` multiplies a's means and
// errors (the power check).
inline bool BlocksAgree(const BlockEstimates& a, const BlockEstimates& b, double familyAlpha,
                        std::string* why = nullptr, Colour scale = Colour(1.0)) {
  const int tests = static_cast<int>(a.blocks.size());
  const double perTest = SidakAlpha(familyAlpha, tests);
  bool agree = true;
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const MeanAndError& x = a.blocks[i];
    const MeanAndError& y = b.blocks[i];
    const double s = scale[static_cast<int>(i % 3)];
    const WelchT w = Welch(s * x.mean, s * x.StandardError(), x.n, y.mean, y.StandardError(), y.n);
    const double limit = StudentTQuantileTwoSided(perTest, w.dof);
    if (std::abs(w.t) > limit + 1e-12) {
      agree = false;
      if (why) {
        *why += "block " + std::to_string(i / 3) + " channel " + std::to_string(i % 3) + ": t " +
                std::to_string(w.t) + " beyond " + std::to_string(limit) + "; ";
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    const MeanAndError& x = a.whole[k];
    const MeanAndError& y = b.whole[k];
    const WelchT w =
        Welch(scale[k] * x.mean, scale[k] * x.StandardError(), x.n, y.mean, y.StandardError(), y.n);
    const double limit = StudentTQuantileTwoSided(1e-4, w.dof);
    if (std::abs(w.t) > limit) {
      agree = false;
      if (why) {
        *why += "whole image, channel " + std::to_string(k) + ": t " + std::to_string(w.t) +
                " beyond " + std::to_string(limit) + "; ";
      }
    }
  }
  return agree;
}

// BlocksAgree, and the power to see a 1% bias: in every channel, 1% of the whole-image
// mean is at least kPowerSigmas standard errors of the difference, and a's channel
// scaled by 1.01 or 0.99 is refused.
inline void ExpectBlocksAgreeWithPower(const std::string& label, const BlockEstimates& a,
                                       const BlockEstimates& b, double familyAlpha = 0.01) {
  std::string why;
  EXPECT_TRUE(BlocksAgree(a, b, familyAlpha, &why)) << label << ": " << why;
  for (int k = 0; k < 3; ++k) {
    const double se = std::hypot(a.whole[k].StandardError(), b.whole[k].StandardError());
    const double sigmas = 0.01 * b.whole[k].mean / se;
    std::printf(
        "%s, channel %d: whole-image means %.6f and %.6f (t %+.2f), a 1%% bias is %.1f "
        "standard errors\n",
        label.c_str(), k, a.whole[k].mean, b.whole[k].mean,
        (a.whole[k].mean - b.whole[k].mean) / se, sigmas);
    EXPECT_GE(sigmas, kPowerSigmas) << label << ", channel " << k;
    for (const double s : {1.01, 0.99}) {
      Colour scale(1.0);
      scale[k] = s;
      EXPECT_FALSE(BlocksAgree(a, b, familyAlpha, nullptr, scale))
          << label << ": channel " << k << " scaled by " << s << " passes";
    }
  }
}

}  // namespace glint::testing
