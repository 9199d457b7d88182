#include "job/RenderReport.hpp"

#include <sys/resource.h>

#include <cstdio>

#include "glint/core/SimdTarget.hpp"
#include "job/Cluster.hpp"
#include "nlohmann/json.hpp"

namespace glint {

namespace {
// The lanes' instruction set (--simd) as it ran: auto resolved to this CPU's widest.
SimdTarget SimdThatRan(const RenderArgs& args) {
  return ResolveSimdTarget(ParseSimdTarget(args.simd).value_or(SimdTarget::Auto));
}
}  // namespace

double PeakResidentMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

std::string StatsJson(const RenderArgs& args, const RenderSetup& s, const Camera& camera,
                      const RenderResult& r) {
  const RenderStats& st = r.stats;
  nlohmann::json j;
  j["scene"] = args.scene;
  j["mode"] = args.mode;
  j["width"] = camera.Width();
  j["height"] = camera.Height();
  j["spp"] = r.spp;
  j["passes"] = r.passes;
  j["threads"] = s.threads;
  j["ranks"] = args.cluster ? args.cluster->Size() : 1;
  j["seed"] = args.seed;
  j["seconds"] = r.seconds;
  if (args.timeBudget > 0.0) j["time_budget"] = args.timeBudget;
  // Rays traced through the scene, by kind; the shadow tests a pixel's shaft answered were
  // not traced and are counted apart.
  j["rays"] = {{"camera", st.cameraRays},         {"reflected", st.reflectedRays},
               {"refracted", st.refractedRays},   {"diffuse", st.diffuseRays},
               {"shadow", st.ShadowRaysTraced()}, {"light", st.lightRays},
               {"traced", st.TracedRays()}};
  j["visibility_answered_without_a_ray"] = st.shadowRaysByShaft;
  // Light tracing (--caustics light): its joins to the eye that added to a pixel.
  j["splats"] = st.splats;
  if (!args.resume.empty()) {
    // What the checkpoint held: this session traced `rays` minus these.
    j["resumed"] = {{"passes", r.resumedPasses},
                    {"camera", r.resumed.cameraRays},
                    {"traced", r.resumed.TracedRays()}};
  }
  const double seconds = r.seconds > 0.0 ? r.seconds : 1e-9;
  j["mrays_per_second"] = static_cast<double>(st.TracedRays()) / seconds / 1e6;
  j["camera_paths_per_second"] = static_cast<double>(st.cameraRays) / seconds;
  j["nonfinite_samples"] = st.nonFiniteSamples;
  j["interrupted"] = r.interrupted;
  j["peak_rss_mib"] = PeakResidentMiB();
  j["fresnel"] = args.fresnel;
  j["sampler"] = args.sampler;
  if (args.mode == "mc") {
    j["mc"] = {{"walls", args.walls},       {"glass", args.glass},
               {"fresnel", args.fresnel},   {"strategy", args.strategy},
               {"branches", args.branches}, {"mirror_light", args.mirrorLight},
               {"caustics", args.caustics}};
  }
  // The camera rays the SIMD lanes traced (the others, one by one): the same image.
  const SimdTarget simd = SimdThatRan(args);
  j["simd"] = {{"target", SimdTargetName(simd)},
               {"lanes", SimdLanes(simd)},
               {"camera_rays_in_lanes", st.laneRays}};
  j["view_plane_distance"] = camera.ViewPlaneDistance();
  return j.dump(2) + "\n";
}

void PrintSummary(const RenderArgs& args, const RenderSetup& s, const RenderResult& r) {
  const RenderStats& st = r.stats;
  const int size = args.cluster ? args.cluster->Size() : 1;
  const std::string ranks = size > 1 ? std::to_string(size) + " ranks x " : "";
  const double traced = static_cast<double>(st.TracedRays());
  const auto spp = static_cast<unsigned long long>(r.spp);
  std::fprintf(stderr,
               "glint: %s %dx%d, %llu rays/pixel (%u pass%s), %s%d thread%s: %.3f s, %.3g rays "
               "traced (camera %.3g, reflected %.3g, refracted %.3g, diffuse %.3g, shadow "
               "%.3g), %.2f Mrays/s; %.3g shadow tests answered by the pixel shafts without a ray",
               args.mode.c_str(), s.width, s.height, spp, r.passes, r.passes == 1 ? "" : "es",
               ranks.c_str(), s.threads, s.threads == 1 ? "" : "s", r.seconds, traced,
               static_cast<double>(st.cameraRays), static_cast<double>(st.reflectedRays),
               static_cast<double>(st.refractedRays), static_cast<double>(st.diffuseRays),
               static_cast<double>(st.ShadowRaysTraced()),
               traced / (r.seconds > 0.0 ? r.seconds : 1e-9) / 1e6,
               static_cast<double>(st.shadowRaysByShaft));
  if (st.cameraRays > 0) {
    const SimdTarget simd = SimdThatRan(args);
    std::fprintf(stderr, "; SIMD %s (%d lane%s) for %.0f%% of the camera rays",
                 SimdTargetName(simd), SimdLanes(simd), SimdLanes(simd) == 1 ? "" : "s",
                 100.0 * static_cast<double>(st.laneRays) / static_cast<double>(st.cameraRays));
  }
  if (st.lightRays > 0) {
    std::fprintf(stderr, "; light tracing %.3g of the rays, %.3g joined to the eye",
                 static_cast<double>(st.lightRays), static_cast<double>(st.splats));
  }
  if (st.nonFiniteSamples > 0) {
    std::fprintf(stderr, ", %llu NaN/Inf samples dropped",
                 static_cast<unsigned long long>(st.nonFiniteSamples));
  }
  std::fprintf(stderr, "\n");
}

}  // namespace glint
