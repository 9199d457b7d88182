#include "commands/RenderCommand.hpp"

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
#include "job/RenderJob.hpp"
#include "job/RenderReport.hpp"

namespace glint {

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
  Camera camera(s.scene.wall, s.scene.camera.eye, s.width, s.height);
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(args, s);
  const RenderResult r = RunPasses(camera, *integrator, args, s);
  if (!cluster.Root())
    return r.interrupted ? 128 + (InterruptSignal() ? InterruptSignal() : SIGINT) : kExitOk;

  const auto target = [&](const std::string& path) {
    return r.interrupted ? PartialPath(path) : path;
  };
  try {
    for (const std::string& path : s.outputs) camera.Save(target(path), s.exposure);
    if (!args.statsPath.empty()) {
      WriteFileAtomically(target(args.statsPath), StatsJson(args, s, camera, r));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return kExitOutputFailed;
  }
  if (r.interrupted) {
    const int signal = InterruptSignal() != 0 ? InterruptSignal() : SIGINT;
    std::fprintf(stderr, "glint: stopped by %s after %.2f s; saved what was rendered to %s\n",
                 signal == SIGTERM ? "SIGTERM" : "SIGINT", r.seconds,
                 PartialPath(s.outputs.front()).c_str());
    return 128 + signal;
  }
  if (!args.quiet) PrintSummary(args, s, r);
  return kExitOk;
}

}  // namespace glint
