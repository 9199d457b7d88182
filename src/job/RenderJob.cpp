#include "job/RenderJob.hpp"

#include <omp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "glint/camera/PassSchedule.hpp"
#include "glint/image/ImageIO.hpp"
#include "glint/scene/SceneLoader.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "job/Checkpoint.hpp"
#include "job/Interrupt.hpp"
#include "job/Progress.hpp"

namespace glint {

double PeakResidentMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

namespace {

// "N" or "WxH" into width and height.
void ParseSize(const std::string& text, int& width, int& height) {
  const auto fail = [&]() {
    throw InputError("--size " + text + ": expected N or WxH with whole numbers in [1, 65536]");
  };
  const auto parse = [&](const std::string& s) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) {
      fail();
    }
    const long v = std::stol(s);
    if (v < 1 || v > 65536) fail();
    return static_cast<int>(v);
  };
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) {
    width = height = parse(text);
  } else {
    width = parse(text.substr(0, x));
    height = parse(text.substr(x + 1));
  }
}

// Refuses an image whose buffers would not fit in this machine's memory.
void CheckMemory(int width, int height, int threads) {
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  // The Pixel array, the linear image for output, the 8-bit display image and its
  // encoding, and each thread's ray-tree arena.
  const double bytes = pixels * (sizeof(Pixel) + sizeof(Colour) + 3.0 + 4.0) +
                       threads * static_cast<double>(4096 * sizeof(Ray));
  const double physical =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (physical > 0.0 && bytes > 0.8 * physical) {
    char message[256];
    std::snprintf(message, sizeof message,
                  "--size %dx%d: the image needs about %.1f GiB of memory, more than this "
                  "machine can give (%.1f GiB)",
                  width, height, bytes / (1 << 30), physical / (1 << 30));
    throw InputError(message);
  }
}

}  // namespace

// Refuses an output whose folder is missing or cannot take a new file: it tries, with
// a temporary file, so that a read-only file system is caught even for root.
void CheckWritable(const std::string& path) {
  const std::filesystem::path p(path);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : ".";
  if (!std::filesystem::is_directory(dir)) {
    throw InputError(path + ": the folder '" + dir.string() + "' does not exist");
  }
  if (std::filesystem::is_directory(p)) {
    throw InputError(path + ": is a folder, expected a file name");
  }
  std::string probe = (dir / ".glint-write-test-XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) {
    throw InputError(path + ": cannot write in the folder '" + dir.string() +
                     "': " + std::strerror(errno));
  }
  ::close(fd);
  std::remove(probe.c_str());
}

// "dir/name.ext" -> "dir/name.partial.ext"
std::string PartialPath(const std::string& path) {
  std::filesystem::path p(path);
  const std::string ext = p.extension().string();
  p.replace_extension();
  return p.string() + ".partial" + ext;
}

RenderSetup Prepare(const RenderArgs& args, bool checkOutputs) {
  if (args.mode != "mc" && !args.monteCarloSwitches.empty()) {
    throw InputError(args.monteCarloSwitches.front() + ": means nothing with --mode " + args.mode +
                     " (a Monte Carlo switch; use --mode mc)");
  }
  for (const std::string& name : args.monteCarloSwitches) {
    if (args.walls != "diffuse" && name.find("mirror-light") != std::string::npos) {
      throw InputError(name + ": means nothing with --walls " + args.walls +
                       " (the light seen in a mirror reaches a wall only with --walls diffuse)");
    }
  }
  RenderSetup s;
  s.scene = LoadScene(args.scene, args.overrides);
  for (const std::string& w : s.scene.warnings)
    std::fprintf(stderr, "glint: warning: %s\n", w.c_str());
  s.mode = args.mode == "mc" ? s.scene.mc : s.scene.whitted;
  s.width = s.scene.camera.width;
  s.height = s.scene.camera.height;
  if (!args.size.empty()) ParseSize(args.size, s.width, s.height);
  s.threads = args.threads > 0          ? args.threads
              : args.cluster != nullptr ? args.cluster->DefaultThreads()
                                        : omp_get_max_threads();
  CheckMemory(s.width, s.height, s.threads);
  // With a time budget, --spp is the rays per pixel of each pass; without it, 0: passes
  // of 1, 2, 4, ... rays (PassSchedule).
  s.raysPerPass = args.spp > 0 ? args.spp : (args.timeBudget > 0.0 ? 0 : s.mode.spp);
  s.exposure = args.exposure > 0.0 ? args.exposure : s.mode.exposure;
  s.outputs = args.outputs;
  if (!checkOutputs) return s;
  if (s.outputs.empty()) {
    s.outputs.push_back(std::filesystem::path(args.scene).stem().string() + ".png");
  }
  for (const std::string& path : s.outputs) {
    FormatFromPath(path);
    CheckWritable(path);
  }
  if (!args.statsPath.empty()) CheckWritable(args.statsPath);
  if (!args.checkpoint.empty()) CheckWritable(args.checkpoint);
  if (!args.resume.empty() && !std::filesystem::is_regular_file(args.resume)) {
    throw InputError("--resume " + args.resume + ": no such checkpoint file");
  }
  return s;
}

SamplerKind SamplerFromArgs(const RenderArgs& args) {
  return ParseSamplerKind(args.sampler).value_or(SamplerKind::Sobol);
}

namespace {
MonteCarloOptions McOptions(const RenderArgs& args, const ModeSettings& mode) {
  using O = MonteCarloOptions;
  O o;
  o.walls = args.walls == "diffuse" ? O::Walls::Diffuse : O::Walls::Terminal;
  o.glass = args.glass == "choose" ? O::Glass::Choose : O::Glass::Split;
  o.fresnel = args.fresnel == "small-angle" ? O::Fresnel::SmallAngle : O::Fresnel::Exact;
  o.strategy = args.strategy == "light"  ? O::Strategy::Light
               : args.strategy == "brdf" ? O::Strategy::Brdf
                                         : O::Strategy::Mis;
  o.branches = args.branches;
  o.mirrorLight = args.mirrorLight == "brdf" ? O::MirrorLight::Brdf : O::MirrorLight::Nee;
  o.maxDepth = mode.maxDepth;
  return o;
}

}  // namespace

std::unique_ptr<Integrator> MakeIntegrator(const RenderArgs& args, const RenderSetup& s) {
  if (args.mode == "mc")
    return std::make_unique<MonteCarloIntegrator>(s.scene, McOptions(args, s.mode));
  const FresnelModel fresnel =
      args.fresnel == "small-angle" ? FresnelModel::SmallAngle : FresnelModel::Exact;
  return std::make_unique<WhittedIntegrator>(s.scene, s.mode.maxDepth, fresnel);
}

void PrepareShaftsIfTheyPay(Camera& camera, const Integrator& integrator, const RenderSetup& s,
                            bool manyPasses) {
  if (manyPasses || s.raysPerPass >= PixelShaft::kPaysFromRaysPerPixel) {
    camera.PrepareShafts(s.scene, integrator.ShadowLights(), s.threads);
  }
}

namespace {

// What a checkpoint belongs to: a resume refuses one whose fields differ.
nlohmann::json RenderIdentity(const RenderArgs& args, const RenderSetup& s) {
  std::ifstream in(args.scene, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  char fingerprint[17];
  std::snprintf(fingerprint, sizeof fingerprint, "%016llx",
                static_cast<unsigned long long>(Fingerprint(bytes)));
  nlohmann::json j = {{"scene file contents", fingerprint},
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
// as it goes; under MPI, spread over the ranks (Cluster), rank 0 deciding for all.
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
  PassSchedule schedule(s.raysPerPass);
  int rays = progressive ? schedule.FirstRays() : s.raysPerPass;
  if (!args.resume.empty()) {
    const CheckpointProgress progress = Resume(camera, args, s, cluster);
    r.passes = progress.passes;
    r.spp = progress.spp;
    r.stats = progress.stats;
    spentBefore = progress.seconds;
    options.skipDone = progress.currentRays > 0;  // a pass under way: its done pixels stay
    if (options.skipDone) {
      rays = progress.currentRays;
    } else if (!progressive) {
      rays = 0;  // the checkpoint holds the finished render
    }
  }
  const nlohmann::json identity = RenderIdentity(args, s);
  double lastSave = elapsed();
  // `stats`: the counters of the finished passes and of the pass under way so far.
  const auto save = [&](int currentRays, const RenderStats& stats) {
    CheckpointProgress progress;
    progress.passes = r.passes;
    progress.spp = r.spp;
    progress.currentRays = currentRays;
    progress.seconds = elapsed();
    progress.stats = stats;
    try {
      SaveCheckpoint(args.checkpoint, identity, camera, progress);
    } catch (const std::exception& e) {  // the render goes on; the next save tries again
      std::fprintf(stderr, "glint: warning: checkpoint not saved: %s\n", e.what());
    }
    lastSave = elapsed();
  };
  RenderStats passStats;
  const std::function<void()> betweenBatches = [&]() {
    if (elapsed() - lastSave < args.checkpointEvery) return;
    RenderStats stats = r.stats;
    stats += passStats;
    save(rays, stats);
  };
  const bool checkpointing = !args.checkpoint.empty() && cluster.Root();
  while (rays > 0) {
    options.raysPerPixel = rays;
    options.pass = r.passes;
    options.firstSample = r.spp;
    label = progressive ? "pass " + std::to_string(r.passes + 1) : "";
    const double before = elapsed();
    passStats = RenderStats{};
    cluster.RenderPass(camera, integrator, options, passStats,
                       checkpointing ? betweenBatches : std::function<void()>());
    r.stats += passStats;
    const double passSeconds = elapsed() - before;
    // One decision for all ranks: rank 0's, with an interrupt anywhere counted.
    const bool stop = !cluster.AllOk(!interrupted.load());
    if (stop) {
      r.interrupted = true;
      break;
    }
    ++r.passes;
    r.spp += static_cast<std::uint64_t>(rays);
    options.skipDone = false;
    rays = progressive ? schedule.Next(rays, passSeconds, args.timeBudget - elapsed()) : 0;
    rays = cluster.Broadcast(rays);
  }
  if (checkpointing) save(r.interrupted ? options.raysPerPixel : 0, r.stats);
  r.seconds = elapsed();
  r.interrupted = r.interrupted || interrupted.load();
  bar.Finish();
  return r;
}

std::string StatsJson(const RenderArgs& args, const RenderSetup& s, const Camera& camera,
                      const RenderResult& r) {
  const RenderStats& st = r.stats;
  nlohmann::json j;
  j["scene"] = args.scene;
  j["mode"] = args.mode;
  j["width"] = camera.Width();
  j["height"] = camera.Height();
  j["spp"] = r.spp;
  j["passes"] = r.passes;
  j["threads"] = s.threads;
  j["ranks"] = args.cluster ? args.cluster->Size() : 1;
  j["seed"] = args.seed;
  j["seconds"] = r.seconds;
  if (args.timeBudget > 0.0) j["time_budget"] = args.timeBudget;
  // Rays traced through the scene, by kind; the shadow tests a pixel's shaft answered were
  // not traced and are counted apart.
  j["rays"] = {{"camera", st.cameraRays},         {"reflected", st.reflectedRays},
               {"refracted", st.refractedRays},   {"diffuse", st.diffuseRays},
               {"shadow", st.ShadowRaysTraced()}, {"traced", st.TracedRays()}};
  j["visibility_answered_without_a_ray"] = st.shadowRaysByShaft;
  const double seconds = r.seconds > 0.0 ? r.seconds : 1e-9;
  j["mrays_per_second"] = static_cast<double>(st.TracedRays()) / seconds / 1e6;
  j["camera_paths_per_second"] = static_cast<double>(st.cameraRays) / seconds;
  j["nonfinite_samples"] = st.nonFiniteSamples;
  j["interrupted"] = r.interrupted;
  j["peak_rss_mib"] = PeakResidentMiB();
  j["fresnel"] = args.fresnel;
  j["sampler"] = args.sampler;
  if (args.mode == "mc") {
    j["mc"] = {{"walls", args.walls},       {"glass", args.glass},
               {"fresnel", args.fresnel},   {"strategy", args.strategy},
               {"branches", args.branches}, {"mirror_light", args.mirrorLight}};
  }
  j["view_plane_distance"] = camera.ViewPlaneDistance();
  return j.dump(2) + "\n";
}

void PrintSummary(const RenderArgs& args, const RenderSetup& s, const RenderResult& r) {
  const RenderStats& st = r.stats;
  const int size = args.cluster ? args.cluster->Size() : 1;
  const std::string ranks = size > 1 ? std::to_string(size) + " ranks x " : "";
  const double traced = static_cast<double>(st.TracedRays());
  const auto spp = static_cast<unsigned long long>(r.spp);
  std::fprintf(stderr,
               "glint: %s %dx%d, %llu rays/pixel (%u pass%s), %s%d thread%s: %.3f s, %.3g rays "
               "traced (camera %.3g, reflected %.3g, refracted %.3g, diffuse %.3g, shadow "
               "%.3g), %.2f Mrays/s; %.3g shadow tests answered by the pixel shafts without a ray",
               args.mode.c_str(), s.width, s.height, spp, r.passes, r.passes == 1 ? "" : "es",
               ranks.c_str(), s.threads, s.threads == 1 ? "" : "s", r.seconds, traced,
               static_cast<double>(st.cameraRays), static_cast<double>(st.reflectedRays),
               static_cast<double>(st.refractedRays), static_cast<double>(st.diffuseRays),
               static_cast<double>(st.ShadowRaysTraced()),
               traced / (r.seconds > 0.0 ? r.seconds : 1e-9) / 1e6,
               static_cast<double>(st.shadowRaysByShaft));
  if (st.nonFiniteSamples > 0) {
    std::fprintf(stderr, ", %llu NaN/Inf samples dropped",
                 static_cast<unsigned long long>(st.nonFiniteSamples));
  }
  std::fprintf(stderr, "\n");
}

}  // namespace glint
