#include "glint/camera/Camera.hpp"

#if defined(_OPENMP)
#include <omp.h>
#endif

#include <algorithm>
#include <atomic>
#include <stdexcept>

#include "glint/scene/Scene.hpp"

namespace glint {

namespace {
// OpenMP's queries, with a serial fallback for builds without OpenMP (the fuzzer's).
int MaxThreads() {
#if defined(_OPENMP)
  return omp_get_max_threads();
#else
  return 1;
#endif
}
int ThreadNumber() {
#if defined(_OPENMP)
  return omp_get_thread_num();
#else
  return 0;
#endif
}
}  // namespace

bool Camera::EyeOnAxis(const Wall& room, vec3 eye) {
  return room.EyeOnAxis(eye);
}

double Camera::ViewPlaneDistanceFor(const Wall& room, vec3 eye, double given) {
  if (given > 0.0) return given;
  // The ray from the eye to a front corner, (c.x +- s/2, c.y +- s/2, front), must pass
  // through the view plane's corner (+-halfWidth, +-halfHeight) at distance d. With the
  // view plane the size of the room's cross-section, similar triangles give
  // d = eye.z - front: the plane lies in the front opening.
  return eye.z - (room.Position().z + room.Size());
}

Pinhole Camera::GeometryFor(const Wall& room, const CameraSettings& settings, int width,
                            int height) {
  const vec3 eye = settings.eye;
  if (width <= 0 || height <= 0) throw std::invalid_argument("image size must be positive");
  if (!EyeOnAxis(room, eye)) {
    throw std::invalid_argument(
        "the eye must lie on the line through the centre of the back wall, in front of "
        "the room's open side");
  }
  const double given = settings.viewPlaneDistance;
  if (given < 0.0 || !std::isfinite(given)) {
    throw std::invalid_argument("the view plane distance must be positive (0: the set-up rule)");
  }
  const vec3 back = room.Centre() - vec3(0.0, 0.0, 0.5 * room.Size());
  const double halfHeight = 0.5 * room.Size();
  // A non-square image keeps square pixels: the plane widens with the aspect ratio.
  const double halfWidth = halfHeight * static_cast<double>(width) / static_cast<double>(height);
  return {eye,
          glm::normalize(back - eye),
          ViewPlaneDistanceFor(room, eye, given),
          halfWidth,
          halfHeight,
          width,
          height};
}

Camera::Camera(const Wall& room, vec3 eye, int width, int height, double viewPlaneDistance)
    : pinhole_(GeometryFor(room, CameraSettings{eye, viewPlaneDistance}, width, height)) {
  pixels_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
}

RenderStats Camera::RenderChunks(const Integrator& integrator, const RenderOptions& options,
                                 int first, int last) {
  const int count = Width() * Height();
  std::atomic<std::size_t> done{static_cast<std::size_t>(first) * kChunk};
  RenderStats total;
  const int threads = options.threads > 0 ? options.threads : MaxThreads();
  if (arenas_.size() < static_cast<std::size_t>(threads))
    arenas_.resize(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    RayTree& trees = arenas_[static_cast<std::size_t>(ThreadNumber())];  // reused for every pixel
    RenderStats stats;
    // Chunks of consecutive pixels, handed out dynamically: the progress counter and
    // the cancel flag are touched once a chunk, not once a pixel.
#pragma omp for schedule(dynamic, 1) nowait
    for (int chunk = first; chunk < last; ++chunk) {
      if (options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed)) continue;
      const int end = std::min(count, (chunk + 1) * kChunk);
      for (int i = chunk * kChunk; i < end; ++i) {
        Pixel& pixel = pixels_[static_cast<std::size_t>(i)];
        if (options.skipDone && pixel.Passes() > options.pass) continue;  // resumed: done
        Sampler sampler(options.sampler, options.seed, static_cast<std::uint64_t>(i), options.pass,
                        options.firstSample, options.raysPerPixel);
        const PixelPass pass =
            pixel.TracePass(*this, i % Width(), i / Width(), options.raysPerPixel, integrator,
                            sampler, trees, stats, false, options.cancel);
        if (pass.complete) {
          pixel.Add(pass);
          // The chunk's light paths go with its first pixel, uncancelled: they are done
          // exactly when it is, which a checkpoint records and a resume reads.
          if (i == chunk * kChunk) TraceChunkLightPaths(integrator, options, chunk, end - i, stats);
        } else if (pass.samples > 0) {
#pragma omp critical(glint_cut_short)
          cutShort_.emplace_back(static_cast<std::size_t>(i), pass);
        }
      }
      const std::size_t finished =
          done.fetch_add(static_cast<std::size_t>(end - chunk * kChunk), std::memory_order_relaxed);
      if (options.progress && ThreadNumber() == 0) {
        options.progress(finished, static_cast<std::size_t>(count));
      }
    }
#pragma omp critical(glint_render_stats)
    total += stats;
  }
  if (options.progress) {
    options.progress(std::min(static_cast<std::size_t>(count),
                              static_cast<std::size_t>(last) * static_cast<std::size_t>(kChunk)),
                     static_cast<std::size_t>(count));
  }
  return total;
}

void Camera::TraceChunkLightPaths(const Integrator& integrator, const RenderOptions& options,
                                  int chunk, int pixels, RenderStats& stats) {
  const int perRay = integrator.LightPathsPerRay();
  if (perRay == 0) return;
  const std::uint64_t perSample =
      static_cast<std::uint64_t>(perRay) * static_cast<std::uint64_t>(pixels);
  const int paths = static_cast<int>(perSample) * options.raysPerPixel;
  // Its own stream, continuing one sobol sequence from pass to pass as a pixel's does.
  Sampler sampler(options.sampler, options.seed, LightStream(chunk), options.pass,
                  options.firstSample * perSample, paths);
  integrator.TraceLightPaths(*this, sampler, paths, stats);
}

void Camera::PrepareShafts(const Scene& scene, PixelShaft::Lights lights, int threads) {
  // Blocks of 4 x 4 pixels first: a block whose shaft is clear passes that on to all
  // its pixels (their shafts lie inside it); in the others each pixel works out what
  // its block did not know. (Measured: quadtrees from 8 or 16 pixels were no faster.)
  constexpr int kBlock = 4;
  const int columns = (Width() + kBlock - 1) / kBlock;
  const int blocks = columns * ((Height() + kBlock - 1) / kBlock);
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads > 0 ? threads : MaxThreads())
  for (int b = 0; b < blocks; ++b) {
    const int x0 = (b % columns) * kBlock;
    const int y0 = (b / columns) * kBlock;
    const int x1 = std::min(Width(), x0 + kBlock);
    const int y1 = std::min(Height(), y0 + kBlock);
    const PixelShaft block = PixelShaft::Compute(scene, *this, lights, x0, y0, x1, y1, {});
    const bool clear = block.Clear(scene, lights);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        pixels_[Index(x, y)].SetShaft(
            clear ? block : PixelShaft::Compute(scene, *this, lights, x, y, x + 1, y + 1, block));
      }
    }
  }
}

void Camera::Clear() {
  for (Pixel& p : pixels_) p.Clear();
  cutShort_.clear();
}

Image Camera::ToImage(int threads) const {
  Image image(Width(), Height());
#pragma omp parallel for num_threads(std::max(threads, 1)) schedule(static)
  for (int y = 0; y < Height(); ++y) {
    for (int x = 0; x < Width(); ++x) image.At(x, y) = PixelAt(x, y).Radiance();
  }
  for (const auto& [i, pass] : cutShort_) {
    Pixel p = pixels_[i];
    p.Add(pass);
    image.At(static_cast<int>(i % static_cast<std::size_t>(Width())),
             static_cast<int>(i / static_cast<std::size_t>(Width()))) = p.Radiance();
  }
  return image;
}

}  // namespace glint
