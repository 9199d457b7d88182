#include "Cli.hpp"

#include <omp.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Progress.hpp"
#include "glint/Camera.hpp"
#include "glint/ImageIO.hpp"
#include "glint/MonteCarloIntegrator.hpp"
#include "glint/SceneLoader.hpp"
#include "glint/WhittedIntegrator.hpp"

namespace glint {

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 bad input (scene file, --set or option value); "
    "2 an output file could not be written.";

struct RenderArgs {
  std::string scene;
  std::string mode = "whitted";
  std::string size;
  int spp = 0;
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

// "N" or "WxH" into width and height.
void ParseSize(const std::string& text, int& width, int& height) {
  const auto fail = [&]() {
    throw InputError("--size " + text + ": expected N or WxH with whole numbers in [1, 65536]");
  };
  const std::size_t x = text.find_first_of("xX");
  const auto parse = [&](const std::string& s) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos) {
      fail();
    }
    const long v = std::stol(s);
    if (v < 1 || v > 65536) fail();
    return static_cast<int>(v);
  };
  if (x == std::string::npos) {
    width = height = parse(text);
  } else {
    width = parse(text.substr(0, x));
    height = parse(text.substr(x + 1));
  }
}

// Refuses outputs whose format is unknown or whose folder cannot be written, before
// any time is spent rendering.
void CheckWritable(const std::string& path) {
  const std::filesystem::path p(path);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : ".";
  if (!std::filesystem::is_directory(dir)) {
    throw InputError(path + ": the folder '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw InputError(path + ": the folder '" + dir.string() + "' is not writable");
  }
  if (std::filesystem::is_directory(p)) {
    throw InputError(path + ": is a folder, expected a file name");
  }
}

void CheckOutputs(const std::vector<std::string>& outputs) {
  for (const std::string& path : outputs) {
    FormatFromPath(path);
    CheckWritable(path);
  }
}

std::string StatsJson(const RenderArgs& args, const Camera& camera, int spp, int threads,
                      double seconds, const RenderStats& s) {
  nlohmann::json j;
  j["scene"] = args.scene;
  j["mode"] = args.mode;
  j["width"] = camera.Width();
  j["height"] = camera.Height();
  j["spp"] = spp;
  j["threads"] = threads;
  j["seed"] = args.seed;
  j["seconds"] = seconds;
  j["rays"] = {{"camera", s.cameraRays},       {"reflected", s.reflectedRays},
               {"refracted", s.refractedRays}, {"diffuse", s.diffuseRays},
               {"shadow", s.shadowRays},       {"total", s.TotalRays()}};
  j["mrays_per_second"] = seconds > 0.0 ? static_cast<double>(s.TotalRays()) / seconds / 1e6 : 0.0;
  j["camera_paths_per_second"] = seconds > 0.0 ? static_cast<double>(s.cameraRays) / seconds : 0.0;
  j["nonfinite_samples"] = s.nonFiniteSamples;
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

int Render(const RenderArgs& args) {
  const Scene scene = LoadScene(args.scene, args.overrides);
  const bool mc = args.mode == "mc";
  const ModeSettings& mode = mc ? scene.mc : scene.whitted;
  int width = scene.camera.width;
  int height = scene.camera.height;
  if (!args.size.empty()) ParseSize(args.size, width, height);
  const int spp = args.spp > 0 ? args.spp : mode.spp;
  const double exposure = args.exposure > 0.0 ? args.exposure : mode.exposure;
  std::vector<std::string> outputs = args.outputs;
  if (outputs.empty()) {
    outputs.push_back(std::filesystem::path(args.scene).stem().string() + ".png");
  }
  CheckOutputs(outputs);
  if (!args.statsPath.empty()) CheckWritable(args.statsPath);

  Camera camera(scene.wall, scene.camera.eye, width, height);
  std::unique_ptr<Integrator> integrator;
  if (mc) {
    integrator = std::make_unique<MonteCarloIntegrator>(scene, McOptions(args, mode));
  } else {
    integrator = std::make_unique<WhittedIntegrator>(scene, mode.maxDepth);
  }
  ProgressBar bar(!args.quiet && StderrIsTerminal());
  RenderOptions options;
  options.raysPerPixel = spp;
  options.seed = args.seed;
  options.threads = args.threads;
  options.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  const int threads = args.threads > 0 ? args.threads : omp_get_max_threads();

  const auto start = std::chrono::steady_clock::now();
  const RenderStats stats = camera.Render(*integrator, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.Finish();

  try {
    for (const std::string& path : outputs) camera.Save(path, exposure);
    if (!args.statsPath.empty()) {
      WriteFileAtomically(args.statsPath, StatsJson(args, camera, spp, threads, seconds, stats));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return kExitOutputFailed;
  }
  if (!args.quiet) {
    const double total = static_cast<double>(stats.TotalRays());
    std::fprintf(
        stderr,
        "glint: %s %dx%d, %d rays/pixel, %d thread%s: %.3f s, %.3g rays "
        "(camera %.3g, reflected %.3g, refracted %.3g, diffuse %.3g, shadow %.3g), "
        "%.2f Mrays/s%s\n",
        args.mode.c_str(), width, height, spp, threads, threads == 1 ? "" : "s", seconds, total,
        static_cast<double>(stats.cameraRays), static_cast<double>(stats.reflectedRays),
        static_cast<double>(stats.refractedRays), static_cast<double>(stats.diffuseRays),
        static_cast<double>(stats.shadowRays), total / seconds / 1e6,
        stats.nonFiniteSamples > 0
            ? (", " + std::to_string(stats.nonFiniteSamples) + " NaN/Inf samples dropped").c_str()
            : "");
  }
  return kExitOk;
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
                   "value for the mode")
      ->check(CLI::Range(1, 1 << 20));
  render
      ->add_option("--threads", args.threads,
                   "Worker threads; default: all cores. The image does not depend on it")
      ->check(CLI::Range(1, 4096));
  render
      ->add_option("--seed", args.seed,
                   "Random seed; the same seed gives the same image for any --threads")
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
                     "shadow) and the NaN/Inf sample count as JSON to this file");
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
