#include "commands/ConvergeCommand.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "glint/camera/PassSchedule.hpp"
#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageError.hpp"
#include "glint/image/ImageIO.hpp"
#include "job/DataFiles.hpp"
#include "job/ExitCode.hpp"
#include "job/Interrupt.hpp"
#include "job/PassLoop.hpp"
#include "job/Subprocess.hpp"

namespace glint {

namespace {

std::vector<double> ParseLadder(const std::string& text, const char* flag) {
  std::vector<double> steps;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(v > 0.0) || (!steps.empty() && v <= steps.back())) {
      throw InputError(std::string(flag) + " " + text +
                       ": expected increasing positive numbers separated by commas");
    }
    steps.push_back(v);
  }
  if (steps.empty()) throw InputError(std::string(flag) + ": expected at least one step");
  return steps;
}

struct Variant {
  std::string name;
  RenderArgs args;
};

// "strategy=mis,light,brdf" -> one RenderArgs per value.
std::vector<Variant> ParseVariants(const ConvergeArgs& a) {
  if (a.compare.empty()) return {{"default", a.render}};
  const std::size_t eq = a.compare.find('=');
  const std::string key = a.compare.substr(0, eq);
  if (eq == std::string::npos) {
    throw InputError("--compare " + a.compare +
                     ": expected KEY=V1,V2,..., e.g. strategy=mis,light,brdf");
  }
  std::vector<Variant> out;
  std::stringstream in(a.compare.substr(eq + 1));
  std::string value;
  while (std::getline(in, value, ',')) {
    Variant v{key + "=" + value, a.render};
    if (key != "fresnel" && key != "sampler")
      v.args.monteCarloSwitches.push_back("--compare " + key);
    const auto allow = [&](const std::vector<std::string>& ok) {
      if (std::find(ok.begin(), ok.end(), value) != ok.end()) return;
      throw InputError("--compare " + a.compare + ": '" + value + "' is not a value of " + key);
    };
    if (key == "strategy") {
      allow(kStrategies);
      v.args.strategy = value;
    } else if (key == "glass") {
      allow(kGlassModes);
      v.args.glass = value;
    } else if (key == "fresnel") {
      allow(kFresnelModels);
      v.args.fresnel = value;
    } else if (key == "walls") {
      allow(kWallModes);
      v.args.walls = value;
    } else if (key == "sampler") {
      allow(kSamplers);
      v.args.sampler = value;
    } else if (key == "mirror-light") {
      allow(kMirrorLightModes);
      v.args.mirrorLight = value;
    } else if (key == "branches") {
      const int b = std::atoi(value.c_str());
      if (b < 1 || b > MonteCarloIntegrator::kMaxBranches || std::to_string(b) != value) {
        throw InputError("--compare " + a.compare + ": branches must be whole numbers in [1, 64]");
      }
      v.args.branches = b;
    } else {
      throw InputError(
          "--compare " + a.compare +
          ": KEY must be strategy, glass, fresnel, walls, branches, sampler or mirror-light");
    }
    out.push_back(v);
  }
  return out;
}

struct Row {
  std::string variant;
  int step;
  std::uint64_t spp;
  double seconds;
  ImageError error;
};

std::string Csv(const std::vector<Row>& rows) {
  std::string out =
      "variant,step,spp,seconds,rmse,rel_mse,block_rmse,bias_r,bias_g,bias_b,firefly_ratio\n";
  char line[512];
  for (const Row& r : rows) {
    std::snprintf(line, sizeof line, "%s,%d,%llu,%.6f,%.8g,%.8g,%.8g,%.6g,%.6g,%.6g,%.6g\n",
                  r.variant.c_str(), r.step, static_cast<unsigned long long>(r.spp), r.seconds,
                  r.error.rmse, r.error.relativeMse, r.error.blockRmse, r.error.bias.x,
                  r.error.bias.y, r.error.bias.z, r.error.fireflyRatio);
    out += line;
  }
  return out;
}

}  // namespace

int RunConverge(const ConvergeArgs& a) {
  const Image reference = ReadImage(a.reference);
  const bool byTime = !a.timeLadder.empty();
  if (byTime == !a.ladder.empty()) {
    throw InputError("give exactly one of --ladder (rays per pixel) and --time-ladder (seconds)");
  }
  const std::vector<double> steps =
      byTime ? ParseLadder(a.timeLadder, "--time-ladder") : ParseLadder(a.ladder, "--ladder");
  std::vector<Variant> variants = ParseVariants(a);
  CheckWritable(a.csv);
  if (!a.chart.empty()) CheckWritable(a.chart);
  const std::atomic<bool>& interrupted = InstallInterruptHandlers();

  std::vector<Row> rows;
  for (Variant& v : variants) {
    if (v.args.size.empty()) {
      v.args.size = std::to_string(reference.Width()) + "x" + std::to_string(reference.Height());
    }
    const RenderSetup s = Prepare(v.args, /*checkOutputs=*/false);
    Camera camera(s.scene.wall, s.scene.camera, s.width, s.height);
    const std::unique_ptr<Integrator> integrator = MakeIntegrator(v.args, s);
    RenderOptions options;
    options.seed = v.args.seed;
    options.sampler = SamplerFromArgs(v.args);
    options.threads = v.args.threads;
    options.cancel = &interrupted;
    // A warm-up pass (threads started, arenas grown, pages touched), then a clean start.
    options.raysPerPixel = 1;
    options.pass = 0xffffffffU;
    camera.Render(*integrator, options);
    camera.Clear();
    const auto prepared = std::chrono::steady_clock::now();
    PrepareShaftsIfTheyPay(camera, *integrator, s, true);  // timed: part of the render's cost
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - prepared).count();
    const Cluster single;  // this process alone
    PassLoop loop(camera, *integrator, options, single);
    PassSchedule schedule(v.args.spp > 0 ? v.args.spp : 0);
    int rays = schedule.FirstRays();
    for (std::size_t k = 0; k < steps.size() && !interrupted.load(); ++k) {
      // Passes up to this step: by rays per pixel, one pass to the next rung; by time,
      // passes of --spp rays (default: 1, 2, 4, ... as the time left allows) until the
      // rung's time is reached.
      do {
        const PassLoop::Pass pass = loop.Render(
            byTime ? rays : static_cast<int>(steps[k] - static_cast<double>(loop.Spp())));
        loop.Count(pass);
        seconds += pass.seconds;
        rays = std::max(schedule.FirstRays(),
                        schedule.Next(pass.rays, pass.seconds, steps[k] - seconds));
      } while (byTime && seconds < steps[k] && !interrupted.load());
      const std::uint64_t spp = loop.Spp();
      const Row row{v.name, static_cast<int>(k), spp, seconds,
                    CompareImages(camera.ToImage(), reference)};
      rows.push_back(row);
      std::fprintf(stderr,
                   "glint converge: %s, %llu rays/pixel, %.3f s: RMSE %.5g, relative MSE %.5g, "
                   "block RMSE %.5g\n",
                   v.name.c_str(), static_cast<unsigned long long>(spp), seconds, row.error.rmse,
                   row.error.relativeMse, row.error.blockRmse);
    }
  }
  WriteFileAtomically(interrupted.load() ? PartialPath(a.csv) : a.csv, Csv(rows));
  if (interrupted.load()) return 128 + InterruptSignal();
  if (a.chart.empty()) return kExitOk;
  // Debian's interpreter, which sees python3-matplotlib, even where another python3
  // (a pyenv, a venv) comes first on PATH.
  const char* python = ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  const std::vector<std::string> command = {python, DataFile("tools/plot_convergence.py"), a.csv,
                                            a.chart};
  if (RunProgram(command) != 0) {
    std::fprintf(stderr, "glint converge: the chart could not be drawn (%s %s %s %s)\n",
                 command[0].c_str(), command[1].c_str(), command[2].c_str(), command[3].c_str());
    return kExitOutputFailed;
  }
  return kExitOk;
}

}  // namespace glint
