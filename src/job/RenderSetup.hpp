// What a render needs from the command line (RenderArgs), checked before any time is
// spent (Prepare), and the integrator and shafts it renders with.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "glint/camera/Camera.hpp"
#include "glint/camera/Integrator.hpp"
#include "glint/scene/Scene.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"

namespace glint {

class Cluster;

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
  std::string mirrorLight = "nee";
  std::string caustics = "off";
  std::string sampler = "sobol";  // the equal-time study's winner (BENCHMARKS.md)
  std::string simd = "auto";      // the lanes' instruction set (SimdTarget)
  // The Monte Carlo switches given on the command line (--walls, ...): with --mode
  // whitted they mean nothing, and Prepare refuses them.
  std::vector<std::string> monteCarloSwitches;
  // Checkpoints: save to `checkpoint` every `checkpointEvery` seconds and at an
  // interrupt; continue the render saved in `resume`.
  std::string checkpoint;
  double checkpointEvery = 60.0;
  std::string resume;
  // The processes of the render (MPI ranks), or this one alone when null.
  const Cluster* cluster = nullptr;
};

// The values each switch of a render takes: the command line and glint view's URL query
// check them against the same lists.
inline const std::vector<std::string> kModes = {"whitted", "mc"};
inline const std::vector<std::string> kWallModes = {"terminal", "diffuse"};
inline const std::vector<std::string> kGlassModes = {"split", "choose"};
inline const std::vector<std::string> kFresnelModels = {"exact", "small-angle"};
inline const std::vector<std::string> kStrategies = {"mis", "light", "brdf"};
inline const std::vector<std::string> kMirrorLightModes = {"nee", "brdf"};
inline const std::vector<std::string> kCausticsModes = {"off", "light"};
inline const std::vector<std::string> kSamplers = {"random", "stratified", "sobol"};
inline const std::vector<std::string> kSimdTargets = {"auto", "scalar", "sse4", "avx2", "avx512"};

// The switches that mean something in Monte Carlo mode only.
inline constexpr const char* kMonteCarloSwitches[] = {"--walls",    "--branches",     "--glass",
                                                      "--strategy", "--mirror-light", "--caustics"};

// The --sampler of the command line (checked by the parser).
SamplerKind SamplerFromArgs(const RenderArgs& args);

// Everything a render needs, checked before any time is spent rendering.
struct RenderSetup {
  Scene scene;
  ModeSettings mode;
  int width = 0;
  int height = 0;
  int raysPerPass = 1;  // 0: passes that double (PassSchedule), for --time without --spp
  int threads = 1;
  double exposure = 1.0;
  std::vector<std::string> outputs;
};

// Loads the scene, prints its warnings, and checks the size, memory and outputs; throws
// InputError on bad input. With checkOutputs false, no output file is needed.
RenderSetup Prepare(const RenderArgs& args, bool checkOutputs = true);
// Refuses an output whose folder is missing or cannot take a new file.
void CheckWritable(const std::string& path);
// "dir/name.ext" -> "dir/name.partial.ext"
std::string PartialPath(const std::string& path);
std::unique_ptr<Integrator> MakeIntegrator(const RenderArgs& args, const RenderSetup& s);
// Camera::PrepareShafts where it pays (PixelShaft::kPaysFromRaysPerPixel): for passes of
// that many rays per pixel or more, and for `manyPasses` renders, which prepare once for
// all their passes (--time, converge).
void PrepareShaftsIfTheyPay(Camera& camera, const Integrator& integrator, const RenderSetup& s,
                            bool manyPasses);

}  // namespace glint
