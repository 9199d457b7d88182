#include "cli/Cli.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/FlagTypo.hpp"
#include "cli/RenderFlags.hpp"
#include "commands/BenchCommand.hpp"
#include "commands/CompareCommand.hpp"
#include "commands/ConvergeCommand.hpp"
#include "commands/RenderCommand.hpp"
#include "commands/TreeCommand.hpp"
#include "commands/ViewCommand.hpp"
#include "glint/core/JsonReader.hpp"
#include "job/Cluster.hpp"
#include "job/DataFiles.hpp"
#include "job/RenderSetup.hpp"
#include "job/Revision.hpp"  // generated in the build tree (cmake/Revision.cmake)

namespace glint {

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 bad input (scene file, --set or option value); 2 an output "
    "file could not be written; 3 (glint compare) the renders disagree with the reference; "
    "130 and 143 stopped by SIGINT or SIGTERM (what was rendered is saved to "
    "FILE.partial.EXT).";

}  // namespace

int RunCli(int argc, char** argv, const Cluster& cluster) {
  CLI::App app{"glint: a small global-illumination renderer (Whitted and Monte Carlo)", "glint"};
  app.footer(kExitCodes);
  app.require_subcommand(1);
  app.set_version_flag("--version", "glint " GLINT_VERSION " (revision " GLINT_REVISION ")");

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
  conv->add_option(
          "--reference", converge.reference,
          "Reference image (PFM or EXR, linear radiance), e.g. a long render of glint itself")
      ->required();
  conv->add_option("--ladder", converge.ladder,
                   "Cumulative rays per pixel at which to measure, e.g. 1,2,4,8,16");
  conv->add_option("--time-ladder", converge.timeLadder,
                   "Cumulative seconds at which to measure instead, e.g. 0.25,0.5,1,2");
  conv->add_option("--compare", converge.compare,
                   "Compare values of one switch in one chart: strategy=mis,light,brdf, "
                   "glass=split,choose, fresnel=exact,small-angle, walls=terminal,diffuse, "
                   "branches=1,2,4, sampler=random,stratified,sobol, mirror-light=nee,brdf or "
                   "caustics=off,light");
  TreeArgs tree;
  CLI::App* treeCommand = app.add_subcommand(
      "tree",
      "Draw the ray trees of one pixel as a Graphviz graph: a picture (-o X.png, .svg, "
      ".pdf) or its text (-o X.dot)");
  treeCommand->footer(kExitCodes);
  AddRenderOptions(treeCommand, tree.render, false);
  treeCommand->add_option("--pixel", tree.pixel, "The pixel, X,Y (0,0 is top left)")->required();
  treeCommand
      ->add_option("-o,--output", tree.output,
                   "X.dot: Graphviz text; X.png, X.svg or X.pdf: the picture Graphviz draws")
      ->capture_default_str();
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
  benchCommand
      ->add_option("--repeat", bench.repeat,
                   "Timed runs per row, the rows taking turns; the median counts")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  benchCommand->add_option("--sampler", bench.sampler, "Sampler: random, stratified or sobol")
      ->check(CLI::IsMember(kSamplers))
      ->capture_default_str();
  benchCommand
      ->add_option("--simd", bench.simd,
                   "Rows of each mode for each of these SIMD targets, e.g. scalar,avx512 (see "
                   "glint render --help)")
      ->delimiter(',')
      ->check(CLI::IsMember(kSimdTargets))
      ->capture_default_str();
  benchCommand->add_option("--json", bench.json, "Also write the table as JSON to this file");

  ViewArgs view;
  CLI::App* viewCommand = app.add_subcommand(
      "view",
      "Watch the render refine in the browser: a local web page with the image, its "
      "exposure, the modes' switches, sliders for scene values, a pixel's ray trees, the "
      "error against a reference and downloads; until SIGINT or SIGTERM. Rendering rests "
      "while no page is open (10 s after the last one asked)");
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
  viewCommand
      ->add_option("--time", view.limits.seconds,
                   "Stop accumulating after this many seconds of rendering (the server stays; "
                   "new settings start again); default: no limit")
      ->check(PositiveNumber());
  viewCommand
      ->add_option("--max-spp", view.limits.spp,
                   "Stop accumulating at this many rays per pixel; default: no limit")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));

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
      ->check(PositiveNumber())
      ->capture_default_str();

  conv->add_option("--csv", converge.csv, "CSV of the measurements")->capture_default_str();
  conv->add_option("--chart", converge.chart,
                   "Log-log charts of relative MSE and of RMSE against time (PNG, drawn with "
                   "matplotlib); empty for none")
      ->capture_default_str();

  // --spp means something else in each of these (they have no --time).
  conv->get_option("--spp")->description(
      "With --time-ladder: the rays per pixel of each pass (default: passes of 1, 2, 4, ... "
      "rays as the time left allows); with --ladder the rungs give the rays");
  treeCommand->get_option("--spp")->description(
      "Rays traced through the pixel, each drawn as a tree (default: 1)");
  viewCommand->get_option("--spp")->description(
      "Rays per pixel of every pass (default: passes that double, or halve, toward about "
      "0.25 s each)");

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
    // A misspelt flag first: it is often why a required one seems missing
    // (`converge --refrence R.pfm`).
    for (const CLI::App* sub : app.get_subcommands()) {
      const std::string message = UnknownFlagMessage(*sub, sub->remaining());
      if (!message.empty()) {
        std::fprintf(stderr, "%s\n", message.c_str());
        return kExitBadInput;
      }
    }
    app.exit(e);
    return kExitBadInput;
  }

  // glint bench without a scene, from another folder: the repository's canonical scene.
  if (*benchCommand && benchCommand->count("scene") == 0 && !std::filesystem::exists(bench.scene)) {
    bench.scene = DataFile("scenes/cornell.json");
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
    if (*render) return RunRender(args, cluster);
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
