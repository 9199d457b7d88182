#include "commands/ConvergeCommand.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "glint/camera/PassSchedule.hpp"
#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageError.hpp"
#include "glint/image/ImageIO.hpp"
#include "glint/image/SlopeFit.hpp"
#include "glint/sampling/Rng.hpp"
#include "job/DataFiles.hpp"
#include "job/ExitCode.hpp"
#include "job/Interrupt.hpp"
#include "job/PassLoop.hpp"
#include "job/RenderAttributes.hpp"
#include "job/RunClock.hpp"
#include "job/Subprocess.hpp"
#include "job/TimedRender.hpp"

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
    } else if (key == "caustics") {
      allow(kCausticsModes);
      v.args.caustics = value;
    } else if (key == "branches") {
      const int b = std::atoi(value.c_str());
      if (b < 1 || b > MonteCarloIntegrator::kMaxBranches || std::to_string(b) != value) {
        throw InputError("--compare " + a.compare + ": branches must be whole numbers in [1, 64]");
      }
      v.args.branches = b;
    } else {
      throw InputError(
          "--compare " + a.compare +
          ": KEY must be strategy, glass, fresnel, walls, branches, sampler, mirror-light "
          "or caustics");
    }
    out.push_back(v);
  }
  return out;
}

// A rung is rendered from scratch, with a seed of its own, again and again: in each of
// kRounds rounds until it has run kFloorSeconds / kRounds of wall time (at least once),
// so kRounds times and kFloorSeconds in all. One preempted time slice cannot move the
// median of its times, and the repeats' spread is the slope's error bar. The rounds pass
// over every rung in turn, and in a rung the variants take turns: a spell of load falls
// on every rung and variant alike, which leaves the slopes alone (measured: with one core
// busy, rungs run one after the other gave slopes 3.6 standard errors apart run to run).
// The error bar resamples whole rounds (SlopeFit's block bootstrap): what a busy spell
// does to a rung is in it.
constexpr int kRounds = 6;
// A --time-ladder rung's time is its budget, not a measurement: three rounds give its
// error's spread at a third of the cost.
constexpr int kTimeRounds = 3;
constexpr int kMaxRepeats = 999;
constexpr double kFloorSeconds = 0.2;
constexpr double kMaxSlopeError = 0.1;
constexpr int kMinRungs = 4;
constexpr double kBusyCores = 0.25;  // other processes' share that makes a timing suspect

struct Repeat {
  int round = 0;
  Timing timing;
  std::uint64_t spp = 0;
  ImageError error;
};

// What a repeat measured, one accessor each (RungResult::Each maps them over the runs).
double WallOf(const Repeat& x) {
  return x.timing.wall;
}
double CpuOf(const Repeat& x) {
  return x.timing.cpu;
}
double SppOf(const Repeat& x) {
  return static_cast<double>(x.spp);
}
double RelMseOf(const Repeat& x) {
  return x.error.relativeMse;
}
double RmseOf(const Repeat& x) {
  return x.error.rmse;
}

struct RungResult {
  std::vector<Repeat> repeats;
  Timing load;  // of the whole rung, every variant's repeats
  std::vector<std::string> warnings;

  double Wall() const {
    double sum = 0.0;
    for (const Repeat& r : repeats) sum += WallOf(r);
    return sum;
  }
  bool RoundDone(int round, int rounds) const {
    double wall = 0.0;
    int count = 0;
    for (const Repeat& r : repeats) {
      if (r.round != round) continue;
      wall += WallOf(r);
      ++count;
    }
    return count >= kMaxRepeats / rounds || (count > 0 && wall >= kFloorSeconds / rounds);
  }
  template <class F>
  std::vector<double> Each(F f) const {
    std::vector<double> out;
    out.reserve(repeats.size());
    for (const Repeat& r : repeats) out.push_back(f(r));
    return out;
  }
};

// One variant's render, prepared once, and what its rungs measured.
struct Study {
  Variant variant;
  TimedRender render;
  std::vector<RungResult> rungs;
  std::vector<std::string> warnings;  // of the whole variant
  Slope relMseByTime;
  Slope rmseByTime;
  Slope relMseBySpp;
};

// Seeds of (rung, repeat): independent streams, far from the small seeds people type
// for their references.
std::uint64_t RepeatSeed(std::uint64_t seed, std::size_t rung, std::size_t repeat) {
  return Pcg32::SplitMix64(seed ^ Pcg32::SplitMix64((rung << 16U) + repeat + 1));
}

// One repeat of a rung: the camera cleared, shafts prepared (as a render pays for them),
// the passes up to `step` rays per pixel (or seconds), timed; the error after the clock.
Repeat RenderRepeat(Study& st, bool byTime, double step, std::uint64_t seed,
                    const Image& reference) {
  Camera& camera = *st.render.camera;
  camera.Clear();
  RenderOptions options = st.render.options;
  options.seed = seed;
  RunClock clock;
  if (byTime || step >= PixelShaft::kPaysFromRaysPerPixel) {
    camera.PrepareShafts(st.render.setup->scene, st.render.integrator->ShadowLights(),
                         st.render.setup->threads);
  }
  const Cluster single;  // this process alone
  PassLoop loop(camera, *st.render.integrator, options, single);
  if (byTime) {
    PassSchedule schedule(st.variant.args.spp > 0 ? st.variant.args.spp : 0);
    int rays = schedule.FirstRays();
    double seconds = clock.Elapsed().wall;
    while (seconds < step && !options.cancel->load()) {
      const PassLoop::Pass pass = loop.Render(rays);
      loop.Count(pass);
      seconds = clock.Elapsed().wall;
      rays = std::max(schedule.FirstRays(), schedule.Next(pass.rays, pass.seconds, step - seconds));
    }
  } else {
    loop.Count(loop.Render(static_cast<int>(step)));
  }
  Repeat r;
  r.timing = clock.Elapsed();
  r.spp = loop.Spp();
  r.error = CompareImages(camera.ToImage(), reference);
  return r;
}

std::string Joined(const std::vector<std::string>& parts) {
  std::string out;
  for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
  for (char& c : out) {
    if (c == ',' || c == '"') c = ' ';  // one CSV field
  }
  return out;
}

std::string Csv(const std::vector<Study>& studies) {
  std::string out =
      "variant,step,spp,seconds,rmse,rel_mse,block_rmse,bias_r,bias_g,bias_b,firefly_ratio,"
      "rel_mse_se,seconds_min,seconds_max,cpu_seconds,repeats,other_cores,slope_rel_mse_time,"
      "slope_rel_mse_time_se,slope_rmse_time,slope_rmse_time_se,slope_rel_mse_spp,"
      "slope_rel_mse_spp_se,warning\n";
  char line[1024];
  for (const Study& st : studies) {
    for (std::size_t k = 0; k < st.rungs.size(); ++k) {
      const RungResult& r = st.rungs[k];
      if (r.repeats.empty()) continue;
      const auto mean = [&](auto f) { return MeanOf(r.Each(f)); };
      const std::vector<double> rel = r.Each(RelMseOf);
      const std::vector<double> walls = r.Each(WallOf);
      const double n = static_cast<double>(rel.size());
      const double relMean = MeanOf(rel);
      double var = 0.0;
      for (const double v : rel) var += (v - relMean) * (v - relMean);
      const double relSe = n > 1 ? std::sqrt(var / (n - 1) / n) : 0.0;
      std::vector<std::string> warnings = st.warnings;
      warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
      std::snprintf(
          line, sizeof line,
          "%s,%zu,%.0f,%.6f,%.8g,%.8g,%.8g,%.6g,%.6g,%.6g,%.6g,%.4g,%.6f,%.6f,%.6f,%zu,%.3f,%.4f,"
          "%.4f,%.4f,%.4f,%.4f,%.4f,%s\n",
          st.variant.name.c_str(), k, MedianOf(r.Each(SppOf)), MedianOf(walls), mean(RmseOf),
          relMean, mean([](const Repeat& x) { return x.error.blockRmse; }),
          mean([](const Repeat& x) { return x.error.bias.x; }),
          mean([](const Repeat& x) { return x.error.bias.y; }),
          mean([](const Repeat& x) { return x.error.bias.z; }),
          mean([](const Repeat& x) { return x.error.fireflyRatio; }), relSe,
          *std::min_element(walls.begin(), walls.end()),
          *std::max_element(walls.begin(), walls.end()), MedianOf(r.Each(CpuOf)), r.repeats.size(),
          r.load.OtherCores(), st.relMseByTime.value, st.relMseByTime.standardError,
          st.rmseByTime.value, st.rmseByTime.standardError, st.relMseBySpp.value,
          st.relMseBySpp.standardError, Joined(warnings).c_str());
      out += line;
    }
  }
  return out;
}

std::string Size(const Image& i) {
  return std::to_string(i.Width()) + "x" + std::to_string(i.Height());
}

// The variant's render, prepared; a reference of another size is refused before any work.
Study Prepared(Variant v, const Image& reference, const std::string& referencePath,
               const std::atomic<bool>& interrupted) {
  if (v.args.size.empty()) v.args.size = Size(reference);
  RenderSetup s = Prepare(v.args, /*checkOutputs=*/false);
  if (s.width != reference.Width() || s.height != reference.Height()) {
    throw InputError("--reference " + referencePath + ": expected an image of the render's size " +
                     std::to_string(s.width) + "x" + std::to_string(s.height) +
                     " (--size), found " + Size(reference));
  }
  Study st;
  st.render = PrepareTimedRender(std::move(s), v.args);
  st.render.options.cancel = &interrupted;
  st.variant = std::move(v);
  return st;
}

// A render whose mean is off from the reference's by more than a factor 2 is compared with
// something else: another scene, mode or light.
void WarnOnMeans(Study& st, const Image& reference, const std::string& referencePath) {
  const double mean = st.render.camera->ToImage().Mean();
  const double ref = reference.Mean();
  if (mean <= 2.0 * ref && ref <= 2.0 * mean) return;
  char text[400];
  std::snprintf(text, sizeof text,
                "the render's mean radiance %.4g is %s the reference's %.4g (%s): is the "
                "reference of this scene and mode?",
                mean, mean > ref ? "more than twice" : "less than half", ref,
                referencePath.c_str());
  st.warnings.emplace_back(text);
}

void Fit(Study& st) {
  std::vector<Rung> byTime;
  std::vector<Rung> rmse;
  std::vector<Rung> bySpp;
  for (const RungResult& r : st.rungs) {
    if (r.repeats.empty()) continue;
    std::vector<int> rounds;
    for (const Repeat& x : r.repeats) rounds.push_back(x.round);
    byTime.push_back({r.Each(WallOf), r.Each(RelMseOf), rounds});
    rmse.push_back({r.Each(WallOf), r.Each(RmseOf), rounds});
    bySpp.push_back({r.Each(SppOf), r.Each(RelMseOf), rounds});
  }
  Pcg32 rng(st.variant.args.seed,
            0x510be);  // the bootstrap's own stream: the same data, the same error bar
  st.relMseByTime = FitSlope(byTime, rng);
  st.rmseByTime = FitSlope(rmse, rng);
  st.relMseBySpp = FitSlope(bySpp, rng);
  char text[200];
  if (st.relMseByTime.points < kMinRungs) {
    std::snprintf(text, sizeof text,
                  "a slope through %d rungs says little: give --ladder at least %d rungs",
                  st.relMseByTime.points, kMinRungs);
    st.warnings.emplace_back(text);
  }
  for (const Slope* s : {&st.relMseByTime, &st.rmseByTime}) {
    if (s->standardError > kMaxSlopeError) {
      std::snprintf(text, sizeof text,
                    "a slope against time with standard error %.2f > %.1f: longer rungs "
                    "(more rays or pixels) or a quieter machine would pin it",
                    s->standardError, kMaxSlopeError);
      st.warnings.emplace_back(text);
      break;
    }
  }
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
  const std::vector<Variant> variants = ParseVariants(a);
  CheckWritable(a.csv);
  if (!a.chart.empty()) CheckWritable(a.chart);
  const std::atomic<bool>& interrupted = InstallInterruptHandlers();

  std::vector<Study> studies;
  for (const Variant& v : variants) {
    studies.push_back(Prepared(v, reference, a.reference, interrupted));
    studies.back().rungs.resize(steps.size());
  }
  // The reference's identity (glint's EXR files carry it) against the command's own.
  CheckSameScene(RenderAttributes(a.render, *studies.front().render.setup, 0),
                 ReadImageAttributes(a.reference), "--reference " + a.reference, "this render");
  const int rounds = byTime ? kTimeRounds : kRounds;
  for (int round = 0; round < rounds && !interrupted.load(); ++round) {
    for (std::size_t k = 0; k < steps.size() && !interrupted.load(); ++k) {
      const RunClock clock;
      for (bool any = true; any && !interrupted.load();) {
        any = false;
        for (Study& st : studies) {
          RungResult& r = st.rungs[k];
          if (r.RoundDone(round, rounds)) continue;
          any = true;
          r.repeats.push_back(RenderRepeat(st, byTime, steps[k],
                                           RepeatSeed(st.variant.args.seed, k, r.repeats.size()),
                                           reference));
          r.repeats.back().round = round;
        }
      }
      const Timing t = clock.Elapsed();
      for (Study& st : studies) st.rungs[k].load += t;
    }
    std::fprintf(stderr, "glint converge: round %d of %d done\n", round + 1, rounds);
  }
  for (std::size_t k = 0; k < steps.size(); ++k) {
    for (Study& st : studies) {
      RungResult& r = st.rungs[k];
      const double others = r.load.OtherCores();
      if (r.repeats.empty()) continue;
      const std::vector<double> walls = r.Each(WallOf);
      char text[200];
      if (r.Wall() < kFloorSeconds) {
        std::snprintf(text, sizeof text, "rung %zu ran %.3f s in all%s: under the floor of %.1f s",
                      k, r.Wall(), interrupted.load() ? " (interrupted)" : "", kFloorSeconds);
        r.warnings.emplace_back(text);
      }
      if (others > kBusyCores) {
        std::snprintf(text, sizeof text,
                      "rung %zu: the machine was busy (%.0f%% of a core taken "
                      "by other processes)",
                      k, 100.0 * others);
        r.warnings.emplace_back(text);
      }
      const double mean = MeanOf(r.Each(RelMseOf));
      std::fprintf(stderr,
                   "glint converge: %s, %.0f rays/pixel, %.4f s (median of %zu, %.4f to %.4f; "
                   "CPU %.4f s): relative MSE %.5g, RMSE %.5g; other processes %.0f%% of a core\n",
                   st.variant.name.c_str(), MedianOf(r.Each(SppOf)), MedianOf(walls),
                   r.repeats.size(), *std::min_element(walls.begin(), walls.end()),
                   *std::max_element(walls.begin(), walls.end()), MedianOf(r.Each(CpuOf)), mean,
                   MeanOf(r.Each(RmseOf)), 100.0 * others);
      for (const std::string& w : r.warnings)
        std::fprintf(stderr, "glint converge: warning: %s\n", w.c_str());
    }
  }
  for (Study& st : studies) {
    WarnOnMeans(st, reference, a.reference);
    Fit(st);
    std::printf(
        "%s: slope %.3f ± %.3f of log relative MSE against log seconds; %.3f ± %.3f of "
        "log RMSE; %.3f ± %.3f of log relative MSE against log rays per pixel (%d rungs)\n",
        st.variant.name.c_str(), st.relMseByTime.value, st.relMseByTime.standardError,
        st.rmseByTime.value, st.rmseByTime.standardError, st.relMseBySpp.value,
        st.relMseBySpp.standardError, st.relMseByTime.points);
    for (const std::string& w : st.warnings) {
      std::fprintf(stderr, "glint converge: warning: %s: %s\n", st.variant.name.c_str(), w.c_str());
    }
  }
  std::fflush(stdout);
  WriteFileAtomically(interrupted.load() ? PartialPath(a.csv) : a.csv, Csv(studies));
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
