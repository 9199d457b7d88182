#include "cli/RenderFlags.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace glint {

CLI::Validator PositiveNumber() {
  return CLI::Validator(
      [](const std::string& v) {
        double x = 0.0;
        const bool number = CLI::detail::lexical_cast(v, x);
        return number && x > 0.0 && std::isfinite(x) ? std::string()
                                                     : "expected a number > 0, found " + v;
      },
      "NUMBER > 0");
}

// With `outputs` false (for converge), the options that name output files are left out.
void AddRenderOptions(CLI::App* render, RenderArgs& args, bool outputs) {
  render->add_option("scene", args.scene, "Scene file (JSON), e.g. scenes/cornell.json")
      ->required();
  render
      ->add_option("--mode", args.mode,
                   "Light transport: 'whitted' (point lights, mirrors, refraction) or 'mc' "
                   "(Monte Carlo with the area light)")
      ->check(CLI::IsMember(kModes))
      ->capture_default_str();
  render->add_option("--size", args.size,
                     "Image size in pixels, N (square) or WxH; default: the scene's camera "
                     "resolution (512x512 for the canonical scene)");
  render
      ->add_option(
          "--spp", args.spp,
          "Rays per pixel, through random points inside it; default: the scene's "
          "value for the mode (with --time: rays per pass; default: passes of 1, 2, 4, ... "
          "rays, each fitting in half the time left)")
      ->check(CLI::Range(1, 1 << 20));
  if (outputs) {
    render
        ->add_option("--time", args.timeBudget,
                     "Render progressively, pass after pass, until SECONDS would be exceeded; "
                     "the summary and --stats give the rays per pixel reached")
        ->check(CLI::Range(1e-3, 1e6));
  }
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
      ->check(PositiveNumber());
  if (outputs)
    render->add_option("-o,--output", args.outputs,
                       "Output file, repeatable; the extension picks the format: .png and .ppm "
                       "(display image), .pfm and .exr (linear radiance). Default: "
                       "SCENE-NAME.png");
  if (outputs) {
    render->add_option("--checkpoint", args.checkpoint,
                       "Save the render's state (every pixel's sums and samples) to this file "
                       "every --checkpoint-every seconds and at an interrupt, atomically; "
                       "--resume continues it");
    render
        ->add_option("--checkpoint-every", args.checkpointEvery,
                     "Seconds between checkpoints (fractions allowed)")
        ->check(CLI::Range(1e-3, 1e9))
        ->capture_default_str();
    render->add_option("--resume", args.resume,
                       "Continue the render saved in this checkpoint; refused for a checkpoint "
                       "of another scene, size, seed or set of flags. Resumed after SIGKILL, the "
                       "image is the same, bit for bit, as a render that ran through");
  }
  if (outputs)
    render->add_option("--stats", args.statsPath,
                       "Write timing, the rays traced by kind (camera, reflected, refracted, "
                       "diffuse, shadow; rays.traced in all), the shadow tests answered "
                       "without a ray, and the NaN/Inf sample count as JSON to this file");
  render->add_option("--set", args.overrides,
                     "Override a scene value by JSON pointer, repeatable: "
                     "--set /objects/1/ior=1.3");
  render
      ->add_option("--walls", args.walls,
                   "Monte Carlo: 'terminal' walls spawn no child and return their direct "
                   "light (the design's default); 'diffuse' walls also spawn a "
                   "cosine-distributed child (full global illumination)")
      ->check(CLI::IsMember(kWallModes))
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
      ->check(CLI::IsMember(kGlassModes))
      ->capture_default_str();
  render
      ->add_option("--fresnel", args.fresnel,
                   "Both modes: glass reflects by the 'exact' Fresnel equations, or by "
                   "the 'small-angle' approximation: the normal-incidence reflectance "
                   "((n-1)/(n+1))^2 at every angle (total internal reflection kept)")
      ->check(CLI::IsMember(kFresnelModels))
      ->capture_default_str();
  render
      ->add_option("--strategy", args.strategy,
                   "Monte Carlo, at Phong objects: 'mis' (light and BRDF sampling, power "
                   "heuristic), 'light' (light sampling only) or 'brdf' (BRDF sampling only)")
      ->check(CLI::IsMember(kStrategies))
      ->capture_default_str();
  render
      ->add_option("--mirror-light", args.mirrorLight,
                   "Monte Carlo with diffuse walls: the light a wall sees in a mirror (a mirror "
                   "cube's faces, a mirror sphere) by 'nee', next-event estimation through the "
                   "mirror, or by 'brdf', only the wall's cosine-sampled rays that find it")
      ->check(CLI::IsMember(kMirrorLightModes))
      ->capture_default_str();
  render
      ->add_option("--caustics", args.caustics,
                   "Monte Carlo with diffuse walls: the caustics a wall receives through the "
                   "glass, mirrors and Phong objects found by 'light' tracing as well (paths "
                   "from the light joined to the eye, weighted against the camera's by "
                   "multiple importance sampling) or by the camera's paths alone ('off')")
      ->check(CLI::IsMember(kCausticsModes))
      ->capture_default_str();
  render
      ->add_option("--sampler", args.sampler,
                   "Both modes: where each random decision's numbers come from: 'random' "
                   "(independent uniforms, the design's random number generator), "
                   "'stratified' (jittered strata for the pixel and the first light point "
                   "and direction) or 'sobol' (an Owen-scrambled Sobol sequence per pixel; "
                   "passes continue it; the default: lowest error at equal time)")
      ->check(CLI::IsMember(kSamplers))
      ->capture_default_str();
  render
      ->add_option(
          "--simd", args.simd,
          "The instruction set of the lanes that trace a pixel's camera rays in lock-step "
          "(with terminal walls or in Whitted mode to their wall where the pixel holds only the "
          "room, elsewhere to their first hit): 'auto' (the widest this CPU runs), 'scalar' (the "
          "same code, one lane), 'sse4' (2 lanes), 'avx2' (4) or 'avx512' (8); every one gives "
          "the same image, bit for bit")
      ->check(CLI::IsMember(kSimdTargets))
      ->capture_default_str();
  render->add_flag("-q,--quiet", args.quiet, "No progress bar and no summary line");
}

// Notes which Monte Carlo switches the command line gave, for Prepare to refuse them
// in Whitted mode (a switch that means nothing is refused, not ignored).
void RecordMonteCarloSwitches(const CLI::App* command, RenderArgs& args) {
  for (const char* name : kMonteCarloSwitches) {
    if (command->count(name) > 0) args.monteCarloSwitches.emplace_back(name);
  }
}

}  // namespace glint
