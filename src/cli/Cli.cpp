#include "cli/Cli.hpp"

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

#include "commands/BenchCommand.hpp"
#include "commands/CompareCommand.hpp"
#include "commands/ConvergeCommand.hpp"
#include "commands/TreeCommand.hpp"
#include "commands/ViewCommand.hpp"
#include "glint/camera/Camera.hpp"
#include "glint/image/ImageIO.hpp"
#include "glint/scene/SceneLoader.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"
#include "job/Interrupt.hpp"
#include "job/RenderJob.hpp"

namespace glint {

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 bad input (scene file, --set or option value); 2 an output "
    "file could not be written; 3 (glint compare) the renders disagree with the reference; "
    "130 and 143 stopped by SIGINT or SIGTERM (what was rendered is saved to "
    "FILE.partial.EXT).";

int Render(const RenderArgs& args, const Cluster& cluster) {
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
      ->check(CLI::PositiveNumber);
  if (outputs)
    render->add_option("-o,--output", args.outputs,
                       "Output file, repeatable; the extension picks the format: .png and .ppm "
                       "(display image), .pfm (linear radiance). Default: SCENE-NAME.png");
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
      ->add_option("--sampler", args.sampler,
                   "Both modes: where each random decision's numbers come from: 'random' "
                   "(independent uniforms, the design's random number generator), "
                   "'stratified' (jittered strata for the pixel and the first light point "
                   "and direction) or 'sobol' (an Owen-scrambled Sobol sequence per pixel; "
                   "passes continue it; the default: lowest error at equal time)")
      ->check(CLI::IsMember(kSamplers))
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

}  // namespace

int RunCli(int argc, char** argv, const Cluster& cluster) {
  CLI::App app{"glint: a small global-illumination renderer (Whitted and Monte Carlo)", "glint"};
  app.footer(kExitCodes);
  app.require_subcommand(1);
  app.set_version_flag("--version", "glint 0.1");

  RenderArgs args;
  CLI::App* render = app.add_subcommand("render", "Render a scene file to one or more images");
  render->footer(kExitCodes);
  AddRenderOptions(render, args, true);

  ConvergeArgs converge;
  CLI::App* conv = app.add_subcommand(
      "converge",
      "Error against a reference image as rays per pixel or time grow: a CSV and a log-log "
      "chart, for one strategy or several (--compare)");
  conv->footer(kExitCodes);
  AddRenderOptions(conv, converge.render, false);
  conv->add_option("--reference", converge.reference,
                   "Reference image (PFM, linear radiance), e.g. a long render of glint itself")
      ->required();
  conv->add_option("--ladder", converge.ladder,
                   "Cumulative rays per pixel at which to measure, e.g. 1,2,4,8,16");
  conv->add_option("--time-ladder", converge.timeLadder,
                   "Cumulative seconds at which to measure instead, e.g. 0.25,0.5,1,2");
  conv->add_option("--compare", converge.compare,
                   "Compare values of one switch in one chart: strategy=mis,light,brdf, "
                   "glass=split,choose, fresnel=exact,small-angle, walls=terminal,diffuse, "
                   "branches=1,2,4, sampler=random,stratified,sobol or mirror-light=nee,brdf");
  TreeArgs tree;
  CLI::App* treeCommand = app.add_subcommand(
      "tree", "Write the ray trees of one pixel as a Graphviz graph (render it with dot -Tpng)");
  treeCommand->footer(kExitCodes);
  AddRenderOptions(treeCommand, tree.render, false);
  treeCommand->add_option("--pixel", tree.pixel, "The pixel, X,Y (0,0 is top left)")->required();
  treeCommand->add_option("-o,--output", tree.output, "Graphviz file")->capture_default_str();
  treeCommand->add_option("--max-nodes", tree.maxNodes, "Draw at most this many nodes")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  BenchArgs bench;
  CLI::App* benchCommand = app.add_subcommand(
      "bench",
      "Throughput of a scene in both modes at one or more thread counts: camera paths/s, "
      "rays traced/s (all kinds) and per thread, speedup, shadow tests answered without a "
      "ray, peak memory (see BENCHMARKS.md)");
  benchCommand->footer(kExitCodes);
  benchCommand->add_option("scene", bench.scene, "Scene file (JSON)")->capture_default_str();
  benchCommand->add_option("--size", bench.size, "Image size, N or WxH")->capture_default_str();
  benchCommand->add_option("--threads", bench.threads, "Thread counts to measure, e.g. 1,2")
      ->delimiter(',')
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  benchCommand->add_option("--mc-spp", bench.mcSpp, "Rays per pixel in Monte Carlo mode")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  benchCommand
      ->add_option("--whitted-spp", bench.whittedSpp,
                   "Rays per pixel in Whitted mode; default: the scene's value")
      ->check(CLI::Range(1, 1 << 20));
  benchCommand->add_option("--modes", bench.modes, "Modes to measure: mc, whitted or both")
      ->delimiter(',')
      ->check(CLI::IsMember(kModes))
      ->capture_default_str();
  benchCommand->add_option("--repeat", bench.repeat, "Timed runs per row; the best one counts")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  benchCommand->add_option("--sampler", bench.sampler, "Sampler: random, stratified or sobol")
      ->check(CLI::IsMember(kSamplers))
      ->capture_default_str();
  benchCommand->add_option("--json", bench.json, "Also write the table as JSON to this file");

  ViewArgs view;
  CLI::App* viewCommand = app.add_subcommand(
      "view",
      "Watch the render refine in the browser: a local web page with the image, its "
      "exposure, the modes' switches, sliders for scene values, a pixel's ray trees, the "
      "error against a reference and downloads; until SIGINT or SIGTERM");
  viewCommand->footer(
      "Exit codes: 0 stopped by SIGINT or SIGTERM; 1 bad input (scene file, --set or option "
      "value) or an address and port that cannot be had.");
  AddRenderOptions(viewCommand, view.render, false);
  viewCommand
      ->add_option("--host", view.host,
                   "Address to listen on; the default is loopback only (this machine). "
                   "0.0.0.0 lets the whole network in")
      ->capture_default_str();
  viewCommand->add_option("--port", view.port, "TCP port; 0 for any free one (printed)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  viewCommand->add_option("--reference", view.reference,
                          "Reference image (PFM or EXR) of the same size: A/B flip, a "
                          "relative-error view and a chart of relative MSE against time");

  CompareArgs compare;
  CLI::App* compareCommand = app.add_subcommand(
      "compare",
      "Bias test: do two independent renders A and B (PFM or EXR) agree with a reference "
      "within their noise? Per block and channel, z from the spread of A - B (and of REF - "
      "REF2 when a second reference is given), and the whole image's mean; one line, exit "
      "code 3 on disagreement");
  compareCommand->footer(kExitCodes);
  compareCommand->add_option("A", compare.a, "First render (PFM or EXR)")->required();
  compareCommand->add_option("B", compare.b, "Second render, independent of A (another seed)")
      ->required();
  compareCommand->add_option("REF", compare.reference, "Reference image (PFM or EXR)")->required();
  compareCommand->add_option(
      "REF2", compare.reference2,
      "A second reference, independent of REF: its noise then counts (without it, REF is "
      "taken as exact)");
  compareCommand->add_option("--block", compare.block, "Block size in pixels")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  compareCommand
      ->add_option("--mean-sigma", compare.meanSigma,
                   "The whole image's mean may differ by this many standard errors")
      ->check(CLI::Range(0.1, 100.0))
      ->capture_default_str();
  compareCommand
      ->add_option("--alpha", compare.familyAlpha,
                   "Chance that an unbiased pair fails any block (Sidak-corrected)")
      ->check(CLI::Range(1e-12, 0.5))
      ->capture_default_str();
  compareCommand
      ->add_option("--scale", compare.scale,
                   "Multiply A and B by this first: a calibration, e.g. 1.005 must disagree")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  conv->add_option("--csv", converge.csv, "CSV of the measurements")->capture_default_str();
  conv->add_option("--chart", converge.chart,
                   "Log-log charts of relative MSE and of RMSE against time (PNG, drawn with "
                   "matplotlib); empty for none")
      ->capture_default_str();

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

  RecordMonteCarloSwitches(render, args);
  args.cluster = &cluster;
  RecordMonteCarloSwitches(conv, converge.render);
  RecordMonteCarloSwitches(treeCommand, tree.render);
  RecordMonteCarloSwitches(viewCommand, view.render);
  if (*viewCommand && viewCommand->count("--quiet") > 0) {
    std::fprintf(stderr, "glint: --quiet: means nothing with glint view (it prints one line)\n");
    return kExitBadInput;
  }
  // One voice: under MPI only rank 0 reports.
  const auto report = [&](const char* prefix, const char* what) {
    if (cluster.Root()) std::fprintf(stderr, "glint: %s%s\n", prefix, what);
  };
  try {
    if (*render) return Render(args, cluster);
    if (*conv) return RunConverge(converge);
    if (*treeCommand) return RunTree(tree);
    if (*benchCommand) return RunBench(bench, cluster);
    if (*compareCommand) return RunCompare(compare);
    if (*viewCommand) return RunView(view);
  } catch (const InputError& e) {
    report("", e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    report("", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    report("error: ", e.what());
    return kExitOutputFailed;
  }
  return kExitBadInput;
}

}  // namespace glint
