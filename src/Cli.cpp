#include "Cli.hpp"

#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Interrupt.hpp"
#include "Progress.hpp"
#include "glint/Camera.hpp"
#include "glint/ImageIO.hpp"
#include "glint/MonteCarloIntegrator.hpp"
#include "glint/SceneLoader.hpp"
#include "glint/WhittedIntegrator.hpp"

namespace glint {

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 bad input (scene file, --set or option value); 2 an output "
    "file could not be written; 130 and 143 stopped by SIGINT or SIGTERM (what was "
    "rendered is saved to FILE.partial.EXT).";

struct RenderArgs {
  std::string scene;
  std::string mode = "whitted";
  std::string size;
  int spp = 0;
  double timeBudget = 0.0;
  int threads = 0;
  std::uint64_t seed = 1;
  double exposure = 0.0;
  std::vector<std::string> outputs;
  std::string statsPath;
  std::vector<std::string> overrides;
  bool quiet = false;
  std::string walls = "terminal";
  std::string glass = "split";
  std::string fresnel = "exact";
  std::string strategy = "mis";
  int branches = 1;
};

// Everything a render needs, checked before any time is spent rendering.
struct RenderSetup {
  Scene scene;
  ModeSettings mode;
  int width = 0;
  int height = 0;
  int raysPerPass = 1;
  int threads = 1;
  double exposure = 1.0;
  std::vector<std::string> outputs;
};

struct RenderResult {
  RenderStats stats;
  double seconds = 0.0;
  std::uint32_t passes = 0;
  bool interrupted = false;
};

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

RenderSetup Prepare(const RenderArgs& args) {
  RenderSetup s;
  s.scene = LoadScene(args.scene, args.overrides);
  for (const std::string& w : s.scene.warnings)
    std::fprintf(stderr, "glint: warning: %s\n", w.c_str());
  s.mode = args.mode == "mc" ? s.scene.mc : s.scene.whitted;
  s.width = s.scene.camera.width;
  s.height = s.scene.camera.height;
  if (!args.size.empty()) ParseSize(args.size, s.width, s.height);
  s.threads = args.threads > 0 ? args.threads : omp_get_max_threads();
  CheckMemory(s.width, s.height, s.threads);
  // With a time budget, --spp is the rays per pixel of each pass (default 1).
  s.raysPerPass = args.spp > 0 ? args.spp : (args.timeBudget > 0.0 ? 1 : s.mode.spp);
  s.exposure = args.exposure > 0.0 ? args.exposure : s.mode.exposure;
  s.outputs = args.outputs;
  if (s.outputs.empty()) {
    s.outputs.push_back(std::filesystem::path(args.scene).stem().string() + ".png");
  }
  for (const std::string& path : s.outputs) {
    FormatFromPath(path);
    CheckWritable(path);
  }
  if (!args.statsPath.empty()) CheckWritable(args.statsPath);
  return s;
}

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
  o.maxDepth = mode.maxDepth;
  return o;
}

std::unique_ptr<Integrator> MakeIntegrator(const RenderArgs& args, const RenderSetup& s) {
  if (args.mode == "mc")
    return std::make_unique<MonteCarloIntegrator>(s.scene, McOptions(args, s.mode));
  return std::make_unique<WhittedIntegrator>(s.scene, s.mode.maxDepth);
}

// One pass, or passes until the time budget would be overspent.
RenderResult RunPasses(Camera& camera, const Integrator& integrator, const RenderArgs& args,
                       const RenderSetup& s) {
  const std::atomic<bool>& interrupted = InstallInterruptHandlers();
  ProgressBar bar(!args.quiet && StderrIsTerminal());
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&]() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const bool progressive = args.timeBudget > 0.0;
  RenderResult r;
  RenderOptions options;
  options.raysPerPixel = s.raysPerPass;
  options.seed = args.seed;
  options.threads = args.threads;
  options.cancel = &interrupted;
  std::string label;
  options.progress = [&](std::size_t done, std::size_t total) {
    const double pass = static_cast<double>(done) / static_cast<double>(total);
    bar.Update(progressive ? elapsed() / args.timeBudget : pass, label.c_str());
  };
  double lastPass = 0.0;
  do {
    options.pass = r.passes;
    label = progressive ? "pass " + std::to_string(r.passes + 1) : "";
    const double before = elapsed();
    r.stats += camera.Render(integrator, options);
    lastPass = elapsed() - before;
    if (interrupted.load()) break;
    ++r.passes;
  } while (progressive && elapsed() + lastPass <= args.timeBudget);
  r.seconds = elapsed();
  r.interrupted = interrupted.load();
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
  j["spp"] = static_cast<std::uint64_t>(r.passes) * static_cast<std::uint64_t>(s.raysPerPass);
  j["passes"] = r.passes;
  j["threads"] = s.threads;
  j["seed"] = args.seed;
  j["seconds"] = r.seconds;
  if (args.timeBudget > 0.0) j["time_budget"] = args.timeBudget;
  j["rays"] = {{"camera", st.cameraRays},       {"reflected", st.reflectedRays},
               {"refracted", st.refractedRays}, {"diffuse", st.diffuseRays},
               {"shadow", st.shadowRays},       {"total", st.TotalRays()}};
  const double seconds = r.seconds > 0.0 ? r.seconds : 1e-9;
  j["mrays_per_second"] = static_cast<double>(st.TotalRays()) / seconds / 1e6;
  j["camera_paths_per_second"] = static_cast<double>(st.cameraRays) / seconds;
  j["nonfinite_samples"] = st.nonFiniteSamples;
  j["interrupted"] = r.interrupted;
  if (args.mode == "mc") {
    j["mc"] = {{"walls", args.walls},
               {"glass", args.glass},
               {"fresnel", args.fresnel},
               {"strategy", args.strategy},
               {"branches", args.branches}};
  }
  j["view_plane_distance"] = camera.ViewPlaneDistance();
  return j.dump(2) + "\n";
}

void PrintSummary(const RenderArgs& args, const RenderSetup& s, const RenderResult& r) {
  const RenderStats& st = r.stats;
  const double total = static_cast<double>(st.TotalRays());
  const unsigned long long spp = static_cast<unsigned long long>(r.passes) * s.raysPerPass;
  std::fprintf(stderr,
               "glint: %s %dx%d, %llu rays/pixel (%u pass%s), %d thread%s: %.3f s, %.3g rays "
               "(camera %.3g, reflected %.3g, refracted %.3g, diffuse %.3g, shadow %.3g), "
               "%.2f Mrays/s",
               args.mode.c_str(), s.width, s.height, spp, r.passes, r.passes == 1 ? "" : "es",
               s.threads, s.threads == 1 ? "" : "s", r.seconds, total,
               static_cast<double>(st.cameraRays), static_cast<double>(st.reflectedRays),
               static_cast<double>(st.refractedRays), static_cast<double>(st.diffuseRays),
               static_cast<double>(st.shadowRays),
               total / (r.seconds > 0.0 ? r.seconds : 1e-9) / 1e6);
  if (st.nonFiniteSamples > 0) {
    std::fprintf(stderr, ", %llu NaN/Inf samples dropped",
                 static_cast<unsigned long long>(st.nonFiniteSamples));
  }
  std::fprintf(stderr, "\n");
}

int Render(const RenderArgs& args) {
  const RenderSetup s = Prepare(args);
  Camera camera(s.scene.wall, s.scene.camera.eye, s.width, s.height);
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(args, s);
  const RenderResult r = RunPasses(camera, *integrator, args, s);

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
    const int signal = InterruptSignal();
    std::fprintf(stderr, "glint: stopped by %s after %.2f s; saved what was rendered to %s\n",
                 signal == SIGTERM ? "SIGTERM" : "SIGINT", r.seconds,
                 PartialPath(s.outputs.front()).c_str());
    return 128 + signal;
  }
  if (!args.quiet) PrintSummary(args, s, r);
  return kExitOk;
}

void AddRenderOptions(CLI::App* render, RenderArgs& args) {
  render->add_option("scene", args.scene, "Scene file (JSON), e.g. scenes/cornell.json")
      ->required();
  render
      ->add_option("--mode", args.mode,
                   "Light transport: 'whitted' (point lights, mirrors, refraction) or 'mc' "
                   "(Monte Carlo with the area light)")
      ->check(CLI::IsMember({"whitted", "mc"}))
      ->capture_default_str();
  render->add_option("--size", args.size,
                     "Image size in pixels, N (square) or WxH; default: the scene's camera "
                     "resolution (512x512 for the canonical scene)");
  render
      ->add_option("--spp", args.spp,
                   "Rays per pixel, through random points inside it; default: the scene's "
                   "value for the mode (with --time: rays per pass, default 1)")
      ->check(CLI::Range(1, 1 << 20));
  render
      ->add_option("--time", args.timeBudget,
                   "Render progressively, pass after pass, until SECONDS would be exceeded; "
                   "the summary and --stats give the rays per pixel reached")
      ->check(CLI::Range(1e-3, 1e6));
  render
      ->add_option("--threads", args.threads,
                   "Worker threads; default: all cores. The image does not depend on it")
      ->check(CLI::Range(1, 4096));
  render
      ->add_option("--seed", args.seed,
                   "Random seed; the same seed gives the same image for any --threads")
      ->check(CLI::Validator(
          [](const std::string& v) {
            const bool digits = !v.empty() && v.size() <= 19 &&
                                v.find_first_not_of("0123456789") == std::string::npos;
            return digits ? std::string() : "expected a whole number >= 0, found " + v;
          },
          "UINT"))
      ->capture_default_str();
  render
      ->add_option("--exposure", args.exposure,
                   "Display mapping: radiance is multiplied by this before the sRGB curve "
                   "(PNG and PPM only); default: the scene's value for the mode")
      ->check(CLI::PositiveNumber);
  render->add_option("-o,--output", args.outputs,
                     "Output file, repeatable; the extension picks the format: .png and .ppm "
                     "(display image), .pfm (linear radiance). Default: SCENE-NAME.png");
  render->add_option("--stats", args.statsPath,
                     "Write timing and ray counts by kind (camera, reflected, refracted, "
                     "diffuse, shadow) and the NaN/Inf sample count as JSON to this file");
  render->add_option("--set", args.overrides,
                     "Override a scene value by JSON pointer, repeatable: "
                     "--set /objects/1/ior=1.3");
  render
      ->add_option("--walls", args.walls,
                   "Monte Carlo: 'terminal' walls spawn no child and return their direct "
                   "light (the design's default); 'diffuse' walls also spawn a "
                   "cosine-distributed child (full global illumination)")
      ->check(CLI::IsMember({"terminal", "diffuse"}))
      ->capture_default_str();
  render
      ->add_option("--branches", args.branches,
                   "Monte Carlo: children spawned at each Phong object hit")
      ->check(CLI::Range(1, MonteCarloIntegrator::kMaxBranches))
      ->capture_default_str();
  render
      ->add_option("--glass", args.glass,
                   "Monte Carlo: 'split' glass spawns a reflected and a refracted child "
                   "weighted by Fresnel; 'choose' spawns one, chosen with Fresnel probability")
      ->check(CLI::IsMember({"split", "choose"}))
      ->capture_default_str();
  render
      ->add_option("--fresnel", args.fresnel,
                   "Monte Carlo: 'exact' Fresnel equations, or 'small-angle': the "
                   "normal-incidence reflectance ((n-1)/(n+1))^2 at every angle")
      ->check(CLI::IsMember({"exact", "small-angle"}))
      ->capture_default_str();
  render
      ->add_option("--strategy", args.strategy,
                   "Monte Carlo, at Phong objects: 'mis' (light and BRDF sampling, power "
                   "heuristic), 'light' (light sampling only) or 'brdf' (BRDF sampling only)")
      ->check(CLI::IsMember({"mis", "light", "brdf"}))
      ->capture_default_str();
  render->add_flag("-q,--quiet", args.quiet, "No progress bar and no summary line");
}

}  // namespace

int RunCli(int argc, char** argv) {
  CLI::App app{"glint: a small global-illumination renderer (Whitted and Monte Carlo)", "glint"};
  app.footer(kExitCodes);
  app.require_subcommand(1);
  app.set_version_flag("--version", "glint 0.1");

  RenderArgs args;
  CLI::App* render = app.add_subcommand("render", "Render a scene file to one or more images");
  render->footer(kExitCodes);
  AddRenderOptions(render, args);

  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) known |= sub->get_name() == argv[1];
    if (!known) {
      std::fprintf(stderr, "glint: unknown command '%s'; try 'glint render SCENE' (glint --help)\n",
                   argv[1]);
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  try {
    if (*render) return Render(args);
  } catch (const InputError& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glint: error: %s\n", e.what());
    return kExitOutputFailed;
  }
  return kExitBadInput;
}

}  // namespace glint
