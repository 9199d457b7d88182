// The Camera: an eye, a view direction, a view plane at some distance, and the array
// of Pixels behind it. The set-up rule of the design places it: the eye lies on the
// line through the centre of the back wall W5, orthogonal to it, and the rays from the
// eye to the room's four front corners pass through the view plane's four corners.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "glint/camera/Integrator.hpp"
#include "glint/camera/Pinhole.hpp"
#include "glint/camera/Pixel.hpp"
#include "glint/camera/RenderStats.hpp"
#include "glint/image/Image.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/scene/Wall.hpp"

namespace glint {

struct RenderOptions {
  int raysPerPixel = 1;  // in this pass
  std::uint64_t seed = 1;
  std::uint32_t pass = 0;  // passes draw independent random numbers
  SamplerKind sampler = SamplerKind::Random;
  // The pixels' sample number of this pass's first ray: the rays of the passes before it
  // (a sobol sequence goes on from there).
  std::uint64_t firstSample = 0;
  // Checked between pixels; when it turns true the pass stops early, leaving the
  // remaining pixels as they were (for SIGINT and SIGTERM).
  const std::atomic<bool>* cancel = nullptr;
  int threads = 0;  // 0: OpenMP's default
  // A resumed pass (a checkpoint's): pixels that have `pass + 1` complete passes already
  // are skipped.
  bool skipDone = false;
  // Called now and then from one thread with (pixels done, pixels in all).
  std::function<void(std::size_t, std::size_t)> progress;
};

class Camera {
 public:
  // Throws std::invalid_argument if the eye is not on the axis of the room in front of
  // its open side, or the resolution is not positive. `viewPlaneDistance` 0 is the
  // set-up rule's; another moves the view plane (its size fixed) nearer or farther,
  // which narrows or widens the field of view, as the design allows.
  Camera(const Wall& room, vec3 eye, int width, int height, double viewPlaneDistance = 0.0);
  // The camera a scene file describes, at width x height pixels.
  Camera(const Wall& room, const CameraSettings& settings, int width, int height)
      : Camera(room, settings.eye, width, height, settings.viewPlaneDistance) {}
  // The distance from the eye to the view plane: `given` if positive, else the set-up
  // rule's, to the room's front.
  static double ViewPlaneDistanceFor(const Wall& room, vec3 eye, double given);

  // The first half of the set-up rule: the eye lies on the axis through the centre of
  // the back wall, orthogonal to it, in front of the room's open side.
  static bool EyeOnAxis(const Wall& room, vec3 eye);

  vec3 Eye() const { return pinhole_.Eye(); }
  vec3 ViewDirection() const { return pinhole_.ViewDirection(); }
  double ViewPlaneDistance() const { return pinhole_.Distance(); }
  // Half the width and height of the view plane, in metres.
  double HalfWidth() const { return pinhole_.HalfWidth(); }
  double HalfHeight() const { return pinhole_.HalfHeight(); }
  int Width() const { return pinhole_.Width(); }
  int Height() const { return pinhole_.Height(); }
  // The geometry alone (the rays, the importance for light tracing).
  const Pinhole& Geometry() const { return pinhole_; }
  // The geometry of the camera a scene file describes, at width x height pixels, without
  // its pixels (the integrators' light tracing needs it before a Camera exists).
  static Pinhole GeometryFor(const Wall& room, const CameraSettings& settings, int width,
                             int height);

  // The point of the view plane at image coordinates (px, py) in [0, W] x [0, H],
  // (0, 0) being the top-left corner of pixel (0, 0).
  vec3 ViewPlanePoint(double px, double py) const { return pinhole_.ViewPlanePoint(px, py); }
  // Unit direction from the eye through image coordinates (px, py).
  vec3 DirectionThrough(double px, double py) const { return pinhole_.DirectionThrough(px, py); }

  // Adds one pass over every pixel, in parallel over pixels. The result depends on the
  // seed and the pass only, never on the number of threads: each pixel has its own
  // random stream for each pass.
  RenderStats Render(const Integrator& integrator, const RenderOptions& options) {
    return RenderChunks(integrator, options, 0, Chunks());
  }
  // The same for the pixels of chunks [first, last) only: a pass may be split into
  // pieces (between which a checkpoint is saved) or spread over processes (MPI), and
  // the pixels end the same. A chunk is kChunk consecutive pixels, row by row.
  static constexpr int kChunk = 64;
  int Chunks() const { return (Width() * Height() + kChunk - 1) / kChunk; }
  RenderStats RenderChunks(const Integrator& integrator, const RenderOptions& options, int first,
                           int last);
  // Works out, for every pixel, what its rays will and will not meet in `scene`
  // (PixelShaft): the integrators then skip the tests whose answer is known. The
  // image is the same with or without; call it again if the scene's geometry changes.
  // `lights`: the shadow rays the integrator casts (Integrator::ShadowLights).
  void PrepareShafts(const Scene& scene, PixelShaft::Lights lights, int threads = 0);

  // Light tracing's contribution c to pixel i, from any thread (Pixel::AddSplat); one
  // too large to add is counted as a non-finite sample.
  void Splat(std::size_t i, Colour c, RenderStats& stats) {
    if (pixels_[i].AddSplat(c)) {
      ++stats.splats;
    } else {
      ++stats.nonFiniteSamples;
    }
  }
  // The stream of chunk `chunk`'s light paths in a pass: a pixel index past the image's,
  // so that no pixel shares it.
  std::uint64_t LightStream(int chunk) const {
    return static_cast<std::uint64_t>(Width()) * static_cast<std::uint64_t>(Height()) +
           static_cast<std::uint64_t>(chunk);
  }

  // Forgets all passes.
  void Clear();
  // Passes a cancel cut short: in the image (what was rendered is saved), not in the
  // pixels (a checkpoint holds complete passes only, which a resume can continue).
  const std::vector<std::pair<std::size_t, PixelPass>>& CutShort() const { return cutShort_; }

  const Pixel& PixelAt(int x, int y) const { return pixels_[Index(x, y)]; }
  // Pixel i of the array, row by row (checkpoints and MPI move pixels by index).
  const Pixel& PixelAt(std::size_t i) const { return pixels_[i]; }
  Pixel& PixelAt(std::size_t i) { return pixels_[i]; }
  // `threads` > 1 fills the image's rows in parallel (a live view does it after each pass).
  Image ToImage(int threads = 1) const;

 private:
  // Chunk `chunk`'s share of the pass's light paths (Integrator::LightPathsPerRay times
  // its `pixels` and the rays per pixel).
  void TraceChunkLightPaths(const Integrator& integrator, const RenderOptions& options, int chunk,
                            int pixels, RenderStats& stats);
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(Width()) +
           static_cast<std::size_t>(x);
  }

  Pinhole pinhole_;
  std::vector<Pixel> pixels_;
  // One ray-tree arena per thread, kept from pass to pass so that progressive rendering
  // allocates nothing after the first pass.
  std::vector<RayTree> arenas_;
  std::vector<std::pair<std::size_t, PixelPass>> cutShort_;
};

}  // namespace glint
