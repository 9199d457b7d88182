#include "job/RenderJob.hpp"

#include <chrono>
#include <cstdio>

#include "glint/camera/PassSchedule.hpp"
#include "glint/core/JsonReader.hpp"
#include "job/Checkpoint.hpp"
#include "job/Interrupt.hpp"
#include "job/PassLoop.hpp"
#include "job/Progress.hpp"

namespace glint {

namespace {

// What a checkpoint belongs to: a resume refuses one whose fields differ.
nlohmann::json RenderIdentity(const RenderArgs& args, const RenderSetup& s) {
  nlohmann::json j = {{"scene file contents", FileFingerprint(args.scene)},
                      {"--set", args.overrides},
                      {"--size", std::to_string(s.width) + "x" + std::to_string(s.height)},
                      {"--seed", args.seed},
                      {"--mode", args.mode},
                      {"--spp", s.raysPerPass},
                      {"--time", args.timeBudget},
                      {"--fresnel", args.fresnel},
                      {"--sampler", args.sampler}};
  if (args.mode == "mc") {
    j["--walls"] = args.walls;
    j["--glass"] = args.glass;
    j["--strategy"] = args.strategy;
    j["--branches"] = args.branches;
    j["--mirror-light"] = args.mirrorLight;
    j["--caustics"] = args.caustics;
  }
  return j;
}

// A resumed render's progress on every rank: rank 0 reads the checkpoint, the others
// learn how far it had come and which pixels have passed (their sums stay on rank 0).
CheckpointProgress Resume(Camera& camera, const RenderArgs& args, const RenderSetup& s,
                          const Cluster& cluster) {
  CheckpointProgress progress;
  std::string error;
  if (cluster.Root()) {
    try {
      progress = LoadCheckpoint(args.resume, RenderIdentity(args, s), camera);
    } catch (const InputError& e) {
      error = e.what();
    }
  }
  if (!cluster.AllOk(error.empty())) throw InputError(error);  // rank 0 reports it
  progress.passes = cluster.Broadcast(progress.passes);
  progress.spp = cluster.Broadcast(progress.spp);
  progress.currentRays = cluster.Broadcast(progress.currentRays);
  progress.seconds = cluster.Broadcast(progress.seconds);
  if (cluster.Distributed()) {
    const std::size_t count =
        static_cast<std::size_t>(camera.Width()) * static_cast<std::size_t>(camera.Height());
    std::vector<std::uint32_t> passes(count);
    for (std::size_t i = 0; i < count; ++i) passes[i] = camera.PixelAt(i).Passes();
    cluster.Broadcast(passes.data(), passes.size() * sizeof(std::uint32_t));
    if (!cluster.Root()) {
      for (std::size_t i = 0; i < count; ++i) camera.PixelAt(i).Restore(Colour(0.0), 0, passes[i]);
    }
  }
  return progress;
}

}  // namespace

// One pass, or passes until the time budget would be overspent; with a checkpoint, saved
// as it goes; under MPI, spread over the ranks (Cluster), rank 0 deciding for all. The
// passes themselves are PassLoop's.
RenderResult RunPasses(Camera& camera, const Integrator& integrator, const RenderArgs& args,
                       const RenderSetup& s) {
  const Cluster single;
  const Cluster& cluster = args.cluster ? *args.cluster : single;
  const std::atomic<bool>& interrupted = InstallInterruptHandlers();
  ProgressBar bar(!args.quiet && cluster.Root() && StderrIsTerminal());
  const auto start = std::chrono::steady_clock::now();
  double spentBefore = 0.0;  // in the sessions before a resume
  const auto elapsed = [&]() {
    return spentBefore +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const bool progressive = args.timeBudget > 0.0;
  PrepareShaftsIfTheyPay(camera, integrator, s, progressive);  // on the clock
  RenderResult r;
  RenderOptions options;
  options.seed = args.seed;
  options.sampler = SamplerFromArgs(args);
  options.threads = s.threads;
  options.cancel = &interrupted;
  std::string label;
  options.progress = [&](std::size_t done, std::size_t total) {
    const double pass = static_cast<double>(done) / static_cast<double>(total);
    bar.Update(progressive ? elapsed() / args.timeBudget : pass, label.c_str());
  };
  PassLoop loop(camera, integrator, options, cluster);
  PassSchedule schedule(s.raysPerPass);
  int rays = progressive ? schedule.FirstRays() : s.raysPerPass;
  if (!args.resume.empty()) {
    const CheckpointProgress progress = Resume(camera, args, s, cluster);
    spentBefore = progress.seconds;
    const bool underWay = progress.currentRays > 0;  // a pass under way: its done pixels stay
    loop.Resume(progress.passes, progress.spp, progress.stats, underWay);
    r.resumed = progress.stats;
    r.resumedPasses = progress.passes;
    if (underWay) {
      rays = progress.currentRays;
    } else if (!progressive) {
      rays = 0;  // the checkpoint holds the finished render
    }
  }
  const nlohmann::json identity = RenderIdentity(args, s);
  double lastSave = elapsed();
  // The counters of the finished passes and of the pass under way so far.
  const auto save = [&](int currentRays) {
    CheckpointProgress progress;
    progress.passes = loop.Passes();
    progress.spp = loop.Spp();
    progress.currentRays = currentRays;
    progress.seconds = elapsed();
    progress.stats = loop.Stats();
    try {
      SaveCheckpoint(args.checkpoint, identity, camera, progress);
    } catch (const std::exception& e) {  // the render goes on; the next save tries again
      std::fprintf(stderr, "glint: warning: checkpoint not saved: %s\n", e.what());
    }
    lastSave = elapsed();
  };
  const std::function<void()> betweenBatches = [&]() {
    if (elapsed() - lastSave < args.checkpointEvery) return;
    save(rays);
  };
  const bool checkpointing = !args.checkpoint.empty() && cluster.Root();
  while (rays > 0) {
    label = progressive ? "pass " + std::to_string(loop.Passes() + 1) : "";
    const PassLoop::Pass pass =
        loop.Render(rays, checkpointing ? betweenBatches : std::function<void()>());
    // One decision for all ranks: rank 0's, with an interrupt anywhere counted.
    const bool stop = !cluster.AllOk(!interrupted.load());
    if (stop) {
      r.interrupted = true;
      break;
    }
    loop.Count(pass);
    rays = progressive ? schedule.Next(rays, pass.seconds, args.timeBudget - elapsed()) : 0;
    rays = cluster.Broadcast(rays);
  }
  if (checkpointing) save(r.interrupted ? rays : 0);
  r.stats = loop.Stats();
  r.passes = loop.Passes();
  r.spp = loop.Spp();
  r.seconds = elapsed();
  r.interrupted = r.interrupted || interrupted.load();
  bar.Finish();
  return r;
}

}  // namespace glint
