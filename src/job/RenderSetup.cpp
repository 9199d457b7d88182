#include "job/RenderSetup.hpp"

#include <omp.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "glint/image/ImageIO.hpp"
#include "glint/scene/SceneLoader.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "job/Cluster.hpp"

namespace glint {

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

// A mode needs its own lights: Monte Carlo the area light, Whitted the point lights.
// Without them the image would be black, which is never what a student meant.
void CheckModeLights(const Scene& scene, const std::string& mode, const std::string& file) {
  if (mode == "mc") {
    if (!scene.light) {
      throw InputError(file +
                       ": Monte Carlo mode is lit by the area_light, and the scene has none "
                       "(add one, see docs/scene-format.md, or render with --mode whitted)");
    }
    if (MaxComponent(scene.light->Radiance()) <= 0.0) {
      std::fprintf(stderr,
                   "glint: warning: %s: the area_light's radiance is 0: the Monte Carlo "
                   "image will be black\n",
                   file.c_str());
    }
    return;
  }
  bool lit = false;
  for (const PointLight& p : scene.pointLights) lit = lit || MaxComponent(p.intensity) > 0.0;
  if (!lit) {
    std::fprintf(stderr,
                 "glint: warning: %s: Whitted mode is lit by the point_lights, and the scene "
                 "has %s: the image will be black (the area_light lights --mode mc only)\n",
                 file.c_str(), scene.pointLights.empty() ? "none" : "only ones of intensity 0");
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
    if (args.walls != "diffuse" && name.find("caustics") != std::string::npos) {
      throw InputError(name + ": means nothing with --walls " + args.walls +
                       " (a caustic lights a wall only with --walls diffuse)");
    }
  }
  const std::optional<SimdTarget> simd = ParseSimdTarget(args.simd);
  if (!simd)
    throw InputError("--simd " + args.simd + ": expected auto, scalar, sse4, avx2 or avx512");
  if (!SimdTargetSupported(*simd)) {
    throw InputError("--simd " + args.simd + ": this CPU does not run it; it runs " +
                     SupportedSimdTargetNames());
  }
  RenderSetup s;
  s.scene = LoadScene(args.scene, args.overrides);
  for (const std::string& w : s.scene.warnings)
    std::fprintf(stderr, "glint: warning: %s\n", w.c_str());
  CheckModeLights(s.scene, args.mode, args.scene);
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
  o.caustics = args.caustics == "light" ? O::Caustics::Light : O::Caustics::Off;
  o.maxDepth = mode.maxDepth;
  o.simd = ParseSimdTarget(args.simd).value_or(SimdTarget::Auto);
  return o;
}

}  // namespace

std::unique_ptr<Integrator> MakeIntegrator(const RenderArgs& args, const RenderSetup& s) {
  if (args.mode == "mc") {
    return std::make_unique<MonteCarloIntegrator>(
        s.scene, McOptions(args, s.mode),
        Camera::GeometryFor(s.scene.wall, s.scene.camera, s.width, s.height));
  }
  const FresnelModel fresnel =
      args.fresnel == "small-angle" ? FresnelModel::SmallAngle : FresnelModel::Exact;
  return std::make_unique<WhittedIntegrator>(
      s.scene, s.mode.maxDepth, fresnel,
      Camera::GeometryFor(s.scene.wall, s.scene.camera, s.width, s.height),
      ParseSimdTarget(args.simd).value_or(SimdTarget::Auto));
}

void PrepareShaftsIfTheyPay(Camera& camera, const Integrator& integrator, const RenderSetup& s,
                            bool manyPasses) {
  if (manyPasses || s.raysPerPass >= PixelShaft::kPaysFromRaysPerPixel) {
    camera.PrepareShafts(s.scene, integrator.ShadowLights(), s.threads);
  }
}

}  // namespace glint
