#include "commands/RenderCommand.hpp"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageIO.hpp"
#include "job/Cluster.hpp"
#include "job/ExitCode.hpp"
#include "job/Interrupt.hpp"
#include "job/RenderAttributes.hpp"
#include "job/RenderJob.hpp"
#include "job/RenderReport.hpp"

namespace glint {

namespace {

// An interrupted pass leaves pixels it never reached without a sample: in the saved image
// they are a magenta and black checkerboard of 8-pixel squares (no render gives it), so
// that nobody takes them for black. Returns how many there are; `rows` gets the number of
// rows from the top in which every pixel was finished.
std::size_t MarkUnrendered(const Camera& camera, Image& image, int& rows) {
  std::vector<bool> started(static_cast<std::size_t>(camera.Width()) * camera.Height(), false);
  for (const auto& cut : camera.CutShort()) started[cut.first] = true;
  std::size_t unrendered = 0;
  rows = camera.Height();
  for (int y = 0; y < camera.Height(); ++y) {
    for (int x = 0; x < camera.Width(); ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * camera.Width() + x;
      const Pixel& p = camera.PixelAt(i);
      if (p.Passes() == 0) rows = std::min(rows, y);
      if (p.Samples() > 0 || started[i]) continue;
      ++unrendered;
      image.At(x, y) = ((x / 8 + y / 8) % 2 == 0) ? Colour(1.0, 0.0, 1.0) : Colour(0.0);
    }
  }
  return unrendered;
}

// What an interrupted render saved, in one line.
void ReportInterrupted(const RenderResult& r, int signal, const std::string& partial,
                       std::size_t unrendered, std::size_t pixels, int rows) {
  std::fprintf(stderr, "glint: stopped by %s after %.2f s; saved what was rendered to %s",
               signal == SIGTERM ? "SIGTERM" : "SIGINT", r.seconds, partial.c_str());
  if (unrendered > 0) {
    std::fprintf(stderr,
                 ": %zu of %zu pixels (%.1f%%) rendered, the first %d rows complete; the rest "
                 "is a magenta and black checkerboard (a render with --time stops between "
                 "passes and saves a whole image)",
                 pixels - unrendered, pixels,
                 100.0 * static_cast<double>(pixels - unrendered) / static_cast<double>(pixels),
                 rows);
  } else {
    std::fprintf(stderr, ": every pixel, %u complete passes (%llu rays per pixel)", r.passes,
                 static_cast<unsigned long long>(r.spp));
  }
  std::fprintf(stderr, "\n");
}

}  // namespace

int RunRender(const RenderArgs& args, const Cluster& cluster) {
  // Every rank checks the input (rank 0 the outputs too); all stop if any rank fails,
  // with one message: rank 0's, or else the first failing rank's.
  RenderSetup s;
  std::string error;
  try {
    s = Prepare(args, /*checkOutputs=*/cluster.Root());
  } catch (const InputError& e) {
    error = e.what();
  }
  std::vector<int> failed;
  if (!cluster.AllOk(error.empty(), &failed)) {
    if (!error.empty() && cluster.Rank() == failed.front()) {
      std::fprintf(stderr, "glint: %s%s\n",
                   cluster.Root() ? "" : ("rank " + std::to_string(cluster.Rank()) + ": ").c_str(),
                   error.c_str());
    }
    return kExitBadInput;
  }
  Camera camera(s.scene.wall, s.scene.camera, s.width, s.height);
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(args, s);
  const RenderResult r = RunPasses(camera, *integrator, args, s);
  if (!cluster.Root())
    return r.interrupted ? 128 + (InterruptSignal() ? InterruptSignal() : SIGINT) : kExitOk;

  const auto target = [&](const std::string& path) {
    return r.interrupted ? PartialPath(path) : path;
  };
  Image image = camera.ToImage();
  int rows = 0;
  const std::size_t unrendered = r.interrupted ? MarkUnrendered(camera, image, rows) : 0;
  try {
    const ImageAttributes identity = RenderAttributes(args, s, r.spp);
    for (const std::string& path : s.outputs) WriteImage(image, target(path), s.exposure, identity);
    if (!args.statsPath.empty()) {
      WriteFileAtomically(target(args.statsPath), StatsJson(args, s, camera, r));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return kExitOutputFailed;
  }
  if (r.interrupted) {
    const int signal = InterruptSignal() != 0 ? InterruptSignal() : SIGINT;
    ReportInterrupted(r, signal, PartialPath(s.outputs.front()), unrendered,
                      static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height), rows);
    return 128 + signal;
  }
  if (!args.quiet) PrintSummary(args, s, r);
  return kExitOk;
}

}  // namespace glint
