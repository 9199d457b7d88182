// Regression images: a low-resolution render against a committed PFM. On failure the
// render and a difference image are written next to the test binary.
#include <gtest/gtest.h>

#include <filesystem>

#include "glint/camera/Camera.hpp"
#include "glint/image/ImageIO.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

using testing::BinaryPath;
using testing::SourcePath;

// Passes when the mean absolute difference is below `meanTolerance` and no more than
// `outlierFraction` of the pixels differ by more than `pixelTolerance` (relative to
// 1 + the reference): a sample that lands on the other side of an edge may move a
// pixel, a wrong renderer moves many.
void CompareWithReference(const Image& image, const std::string& name, double meanTolerance,
                          double pixelTolerance, double outlierFraction) {
  const std::string reference = SourcePath("tests/data/" + name + ".pfm");
  if (!std::filesystem::exists(reference)) {
    WritePfm(image, BinaryPath(name + ".pfm"));
    FAIL() << "no reference " << reference << "; wrote " << BinaryPath(name + ".pfm")
           << " (tools/update-references regenerates them all)";
  }
  const Image ref = ReadPfm(reference);
  ASSERT_EQ(ref.Width(), image.Width());
  ASSERT_EQ(ref.Height(), image.Height());
  Image diff(ref.Width(), ref.Height());
  double sum = 0.0;
  int outliers = 0;
  for (int y = 0; y < ref.Height(); ++y) {
    for (int x = 0; x < ref.Width(); ++x) {
      const Colour d = glm::abs(image.At(x, y) - ref.At(x, y));
      diff.At(x, y) = d;
      sum += d.x + d.y + d.z;
      if (MaxComponent(d / (Colour(1.0) + ref.At(x, y))) > pixelTolerance) ++outliers;
    }
  }
  const double pixels = static_cast<double>(ref.Width() * ref.Height());
  const double mean = sum / (3.0 * pixels);
  const bool ok = mean <= meanTolerance && outliers <= outlierFraction * pixels;
  if (!ok) {
    WritePfm(image, BinaryPath(name + "-actual.pfm"));
    WritePfm(diff, BinaryPath(name + "-diff.pfm"));
  }
  EXPECT_TRUE(ok) << name << ": mean |difference| " << mean << " (tolerance " << meanTolerance
                  << "), " << outliers << " pixels off by more than " << pixelTolerance
                  << "; wrote " << BinaryPath(name + "-diff.pfm");
}

// Renders the canonical scene at size x size with seed 1 and the command line's default
// sampler (sobol); no sample may be NaN or Inf.
Image RenderCanonical(const Scene& scene, const Integrator& integrator, int size, int spp) {
  Camera camera(scene.wall, scene.camera, size, size);
  camera.PrepareShafts(scene, integrator.ShadowLights());  // as the renderer does
  RenderOptions options;
  options.raysPerPixel = spp;
  options.seed = 1;
  options.sampler = SamplerKind::Sobol;
  const RenderStats stats = camera.Render(integrator, options);
  EXPECT_EQ(stats.nonFiniteSamples, 0u);
  return camera.ToImage();
}

TEST(Regression, WhittedCanonical64) {
  const Scene scene = testing::CanonicalScene();
  const WhittedIntegrator integrator(scene, scene.whitted.maxDepth);
  CompareWithReference(RenderCanonical(scene, integrator, 64, 4), "whitted-cornell-64", 1e-4, 1e-3,
                       0.005);
}

TEST(Regression, MonteCarloCanonical32) {
  const Scene scene = testing::CanonicalScene();
  const MonteCarloIntegrator integrator(scene, {});
  // Same seed, same image; the tolerance absorbs a few paths that round-off may send
  // another way on another compiler.
  CompareWithReference(RenderCanonical(scene, integrator, 32, 16), "mc-cornell-32", 2e-3, 1e-2,
                       0.02);
}

}  // namespace
}  // namespace glint
