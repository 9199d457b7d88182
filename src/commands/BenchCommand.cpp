#include "commands/BenchCommand.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

#include "glint/core/SimdTarget.hpp"
#include "glint/image/ImageIO.hpp"
#include "glint/image/SlopeFit.hpp"
#include "job/Cluster.hpp"
#include "job/ExitCode.hpp"
#include "job/RenderReport.hpp"
#include "job/RunClock.hpp"
#include "job/TimedRender.hpp"
#include "nlohmann/json.hpp"

namespace glint {

namespace {

struct Row {
  std::string mode;
  std::string simd;  // the lanes' target as it ran ("-": the MPI bench's row, auto)
  int spp = 0;
  int threads = 0;
  double seconds = 0.0;  // the median of the runs
  double fastest = 0.0;
  double slowest = 0.0;
  double cpu = 0.0;  // the median of the runs' CPU time, every thread's
  RenderStats stats;
};

// One row's render, prepared once; its runs are timed in turn with the other rows' (a
// spell of load falls on all of them, not on one).
struct Case {
  TimedRender render;
  std::vector<double> walls;
  std::vector<double> cpus;
  RenderStats stats;
};

// The render a row measures: the bench's scene, size and sampler in one mode.
RenderArgs RowArgs(const BenchArgs& args, const std::string& mode, int threads,
                   const std::string& simd = "auto") {
  RenderArgs r;
  r.simd = simd;
  r.scene = args.scene;
  r.mode = mode;
  r.size = args.size;
  r.threads = threads;
  r.spp = mode == "mc" ? args.mcSpp : args.whittedSpp;
  r.sampler = args.sampler;
  return r;
}

Case Prepared(const BenchArgs& args, const std::string& mode, int threads,
              const std::string& simd = "auto") {
  const RenderArgs r = RowArgs(args, mode, threads, simd);
  Case c{PrepareTimedRender(Prepare(r, false), r), {}, {}, {}};
  c.render.options.raysPerPixel = c.render.setup->raysPerPass;
  return c;
}

// One timed render of one pass, shafts prepared on the clock as glint render does.
void Run(Case& c) {
  TimedRender& r = c.render;
  r.camera->Clear();
  const RunClock clock;
  PrepareShaftsIfTheyPay(*r.camera, *r.integrator, *r.setup, false);
  c.stats = r.camera->Render(*r.integrator, r.options);
  const Timing t = clock.Elapsed();
  c.walls.push_back(t.wall);
  c.cpus.push_back(t.cpu);
}

// The SIMD targets a mode's rows run: the list, in each mode.
std::vector<std::string> SimdOf(const BenchArgs& args, const std::string& /*mode*/) {
  return args.simd;
}

Row RowOf(const Case& c, const std::string& mode, const std::string& simd, int threads) {
  const std::string ran =
      simd == "-"
          ? simd
          : SimdTargetName(ResolveSimdTarget(ParseSimdTarget(simd).value_or(SimdTarget::Auto)));
  Row row{mode,
          ran,
          c.render.setup->raysPerPass,
          threads,
          MedianOf(c.walls),
          *std::min_element(c.walls.begin(), c.walls.end()),
          *std::max_element(c.walls.begin(), c.walls.end()),
          MedianOf(c.cpus),
          c.stats};
  return row;
}

// `repeat` timed renders of one row on its own (the MPI bench's one-rank row).
Row Measure(const BenchArgs& args, const std::string& mode, int threads) {
  Case c = Prepared(args, mode, threads);
  for (int i = 0; i < args.repeat; ++i) Run(c);
  return RowOf(c, mode, "-", threads);
}

std::string ToJson(const BenchArgs& args, const std::vector<Row>& rows, double otherCores) {
  nlohmann::json j;
  j["other_processes_cores"] = otherCores;
  j["scene"] = args.scene;
  j["size"] = args.size;
  j["repeat"] = args.repeat;
  j["peak_rss_mib"] = PeakResidentMiB();
  for (const Row& row : rows) {
    const double rays = static_cast<double>(row.stats.TracedRays());
    j["runs"].push_back({{"mode", row.mode},
                         {"simd", row.simd},
                         {"spp", row.spp},
                         {"threads", row.threads},
                         {"seconds", row.seconds},
                         {"seconds_min", row.fastest},
                         {"seconds_max", row.slowest},
                         {"cpu_seconds", row.cpu},
                         {"sampler", args.sampler},
                         {"rays_traced", row.stats.TracedRays()},
                         {"visibility_answered_without_a_ray", row.stats.shadowRaysByShaft},
                         {"camera_paths", row.stats.cameraRays},
                         {"mrays_per_second", rays / row.seconds / 1e6},
                         {"mrays_per_second_per_thread", rays / row.seconds / 1e6 / row.threads}});
  }
  return j.dump(2) + "\n";
}

// Under MPI: one rank with one thread, then every rank with one thread each, the pass
// spread over them as glint render spreads it; the speedup and the communication.
int RunBenchRanks(const BenchArgs& args, const Cluster& cluster) {
  if (cluster.Root()) {
    std::printf("glint bench: %s, %s pixels, median of %d run%s, one thread per rank\n",
                args.scene.c_str(), args.size.c_str(), args.repeat, args.repeat == 1 ? "" : "s");
    std::printf("%-8s %5s %6s %9s %9s %12s %8s %9s %11s\n", "mode", "spp", "ranks", "seconds",
                "Mrays/s", "Mrays/s/rank", "speedup", "messages", "bytes");
  }
  for (const std::string& mode : args.modes) {
    Row one;
    if (cluster.Root()) one = Measure(args, mode, 1);
    const RenderArgs r = RowArgs(args, mode, 1);
    TimedRender t = PrepareTimedRender(Prepare(r, false), r);  // warmed up on every rank
    const RenderSetup& s = *t.setup;
    Camera& camera = *t.camera;
    const Integrator& integrator = *t.integrator;
    RenderOptions& options = t.options;
    options.raysPerPixel = s.raysPerPass;
    std::vector<double> times;
    RenderStats runStats;
    std::uint64_t messages = 0;
    std::uint64_t bytes = 0;
    for (int i = 0; i < args.repeat; ++i) {
      camera.Clear();
      cluster.Barrier();
      const std::uint64_t m0 = cluster.MessagesSent();
      const std::uint64_t b0 = cluster.BytesSent();
      const auto start = std::chrono::steady_clock::now();
      PrepareShaftsIfTheyPay(camera, integrator, s, false);
      RenderStats stats;
      cluster.RenderPass(camera, integrator, options, stats, {});
      cluster.Barrier();
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // Rank 0's own messages and bytes; the other ranks' are added below.
      const std::uint64_t m = cluster.MessagesSent() - m0;
      const std::uint64_t b = cluster.BytesSent() - b0;
      times.push_back(seconds);
      runStats = stats;  // every run does the same work
      messages = m;
      bytes = b;
    }
    const double median = MedianOf(times);
    std::uint64_t all[2] = {messages, bytes};
    cluster.SumOnRoot(all, 2);
    if (cluster.Root()) {
      const double rays = static_cast<double>(runStats.TracedRays()) / median / 1e6;
      std::printf("%-8s %5d %6d %9.3f %9.2f %12.2f %8s %9s %11s\n", mode.c_str(), one.spp, 1,
                  one.seconds, static_cast<double>(one.stats.TracedRays()) / one.seconds / 1e6,
                  static_cast<double>(one.stats.TracedRays()) / one.seconds / 1e6, "1.00", "0",
                  "0");
      std::printf("%-8s %5d %6d %9.3f %9.2f %12.2f %8.2f %9llu %11llu\n", mode.c_str(),
                  s.raysPerPass, cluster.Size(), median, rays, rays / cluster.Size(),
                  one.seconds / median, static_cast<unsigned long long>(all[0]),
                  static_cast<unsigned long long>(all[1]));
      std::fflush(stdout);
    }
  }
  return kExitOk;
}

}  // namespace

int RunBench(const BenchArgs& args, const Cluster& cluster) {
  if (cluster.Distributed()) return RunBenchRanks(args, cluster);
  if (!args.json.empty()) CheckWritable(args.json);
  {  // a bad scene or size fails here, before the table starts
    RenderArgs check;
    check.scene = args.scene;
    check.size = args.size;
    for (const std::string& simd : args.simd) {  // and a SIMD target this CPU lacks
      check.simd = simd;
      Prepare(check, false);
    }
  }
  const bool square = args.size.find_first_of("xX") == std::string::npos;
  std::printf(
      "glint bench: %s, %s%s%s pixels, median of %d run%s (the rows take turns), seed 1, "
      "sampler %s; rays traced (a shadow test a pixel's shaft answered is not a ray: "
      "'shaft M/s')\n",
      args.scene.c_str(), args.size.c_str(), square ? "x" : "", square ? args.size.c_str() : "",
      args.repeat, args.repeat == 1 ? "" : "s", args.sampler.c_str());
  std::vector<Case> cases;
  for (const std::string& mode : args.modes) {
    for (const std::string& simd : SimdOf(args, mode)) {
      for (const int threads : args.threads) {
        cases.push_back(Prepared(args, mode, threads, simd == "-" ? "auto" : simd));
      }
    }
  }
  const RunClock clock;
  for (int i = 0; i < args.repeat; ++i) {
    for (Case& c : cases) Run(c);
  }
  const double others = clock.Elapsed().OtherCores();
  std::printf("%-8s %-7s %5s %7s %9s %15s %11s %9s %14s %8s %11s\n", "mode", "simd", "spp",
              "threads", "seconds", "(min - max)", "Mpaths/s", "Mrays/s", "Mrays/s/thread",
              "speedup", "shaft M/s");
  std::vector<Row> rows;
  std::size_t next = 0;
  for (const std::string& mode : args.modes) {
    double first = 0.0;  // speedups are relative to the mode's first row
    for (const std::string& simd : SimdOf(args, mode)) {
      for (const int threads : args.threads) {
        const Row row = RowOf(cases[next++], mode, simd, threads);
        if (first == 0.0) first = row.seconds;
        const double rays = static_cast<double>(row.stats.TracedRays()) / row.seconds / 1e6;
        char spread[32];
        std::snprintf(spread, sizeof spread, "(%.3f - %.3f)", row.fastest, row.slowest);
        std::printf("%-8s %-7s %5d %7d %9.3f %15s %11.2f %9.2f %14.2f %8.2f %11.2f\n", mode.c_str(),
                    row.simd.c_str(), row.spp, threads, row.seconds, spread,
                    static_cast<double>(row.stats.cameraRays) / row.seconds / 1e6, rays,
                    rays / threads, first / row.seconds,
                    static_cast<double>(row.stats.shadowRaysByShaft) / row.seconds / 1e6);
        rows.push_back(row);
      }
    }
  }
  std::printf("other processes took %.0f%% of a core during the runs%s\n", 100.0 * others,
              others > 0.25 ? ": the machine was busy, and the times and speedups are "
                              "not glint's alone"
                            : "");
  std::printf("peak memory (resident): %.1f MiB\n", PeakResidentMiB());
  if (!args.json.empty()) WriteFileAtomically(args.json, ToJson(args, rows, others));
  return kExitOk;
}

}  // namespace glint
