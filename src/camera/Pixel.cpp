#include "glint/camera/Pixel.hpp"

#include "glint/camera/Camera.hpp"

namespace glint {

PixelPass Pixel::TracePass(const Camera& camera, int x, int y, int rays,
                           const Integrator& integrator, Sampler& sampler, RayTree& trees,
                           RenderStats& stats, bool keepTrees,
                           const std::atomic<bool>* cancel) const {
  const double importance = 1.0 / rays;  // all rays of a pixel weigh the same
  PixelPass pass;
  trees.Clear();
  for (int i = 0; i < rays; ++i) {
    if (cancel != nullptr && (i & 255) == 255 && cancel->load(std::memory_order_relaxed)) {
      pass.complete = false;
      break;
    }
    if (!keepTrees) trees.Clear();
    sampler.StartSample(i);
    const Sample2 p = sampler.Get2D(SampleDimension::kPixel);  // a point inside the pixel
    const double px = x + p.u;
    const double py = y + p.v;
    Ray ray;
    ray.start = camera.Eye();
    ray.direction = camera.DirectionThrough(px, py);
    ray.weight = Colour(importance);
    ray.importance = Colour(importance);
    ray.kind = RayKind::Camera;
    const std::uint32_t root = trees.Add(ray);
    ++stats.cameraRays;
    const Colour c = integrator.Trace(trees, root, shaft_, sampler, stats);
    if (!IsFinite(c)) {  // counted and dropped, never averaged in
      ++stats.nonFiniteSamples;
      continue;
    }
    // Radiance() = sum_i C_i / N over the finite samples: each first ray's colour times
    // its importance 1/N. Dropped samples (and rays a cancel cut short) do not darken it.
    pass.sum += c;
    ++pass.samples;
  }
  return pass;
}

}  // namespace glint
