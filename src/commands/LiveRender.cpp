#include "commands/LiveRender.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "commands/ViewSettings.hpp"
#include "glint/camera/PassSchedule.hpp"
#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageError.hpp"
#include "glint/scene/SceneLoader.hpp"
#include "job/PassLoop.hpp"

namespace glint {

namespace {

// The error history keeps at most this many points: every other one goes when it is full
// (the chart is log-log, so the early points matter as much as the late ones).
constexpr std::size_t kMaxErrorPoints = 2000;

void Thin(std::vector<std::array<double, 2>>& points) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points.size(); i += 2) points[kept++] = points[i];
  points.resize(kept);
}

// The steady clock in nanoseconds, for an atomic.
std::int64_t Now() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::string RgbePixels(const Image& image) {
  const std::vector<Colour>& pixels = image.Pixels();
  std::string bytes(pixels.size() * 4, '\0');
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const float rgb[3] = {static_cast<float>(pixels[i].x), static_cast<float>(pixels[i].y),
                          static_cast<float>(pixels[i].z)};
    const float m = std::max({rgb[0], rgb[1], rgb[2]});
    if (!(m > 1e-32F) || !std::isfinite(m)) continue;  // black
    int e = 0;
    const float scale = std::frexp(m, &e) * 256.0F / m;  // m * scale in [128, 256)
    for (int k = 0; k < 3; ++k) {
      bytes[4 * i + k] =
          static_cast<char>(static_cast<unsigned char>(std::max(rgb[k], 0.0F) * scale));
    }
    bytes[4 * i + 3] = static_cast<char>(static_cast<unsigned char>(e + 128));
  }
  return bytes;
}

LiveRender::LiveRender(const RenderArgs& args, std::optional<Image> reference, LiveLimits limits)
    : reference_(std::move(reference)), limits_(limits), lastAsked_(Now()), job_(MakeJob(args, 1)) {
  CheckReference(job_->setup);
  thread_ = std::thread([this]() { Loop(); });
}

void LiveRender::CheckReference(const RenderSetup& s) const {
  if (reference_ && (reference_->Width() != s.width || reference_->Height() != s.height)) {
    throw InputError("--reference: expected an image of " + std::to_string(s.width) + "x" +
                     std::to_string(s.height) + " pixels (the render's size), found " +
                     std::to_string(reference_->Width()) + "x" +
                     std::to_string(reference_->Height()));
  }
}

LiveRender::~LiveRender() {
  Stop();
}

void LiveRender::Stop() {
  stop_ = true;
  restart_ = true;
  if (thread_.joinable()) thread_.join();
}

std::shared_ptr<const LiveJob> LiveRender::MakeJob(const RenderArgs& args,
                                                   std::uint64_t generation) {
  auto job = std::make_shared<LiveJob>();
  job->args = args;
  job->setup = Prepare(args, /*checkOutputs=*/false);
  job->document = LoadSceneDocument(args.scene, args.overrides);
  const Scene& scene = job->setup.scene;
  job->tunables = Tunables(
      job->document,
      Camera::ViewPlaneDistanceFor(scene.wall, scene.camera.eye, scene.camera.viewPlaneDistance));
  job->integrator = MakeIntegrator(args, job->setup);
  job->generation = generation;
  return job;
}

void LiveRender::Check(const RenderArgs& args) {
  MakeJob(args, 0);
}

void LiveRender::Asked() {
  lastAsked_ = Now();
}

double LiveRender::SecondsSinceAsked() const {
  return 1e-9 * static_cast<double>(Now() - lastAsked_.load());
}

std::string LiveRender::Status() const {
  switch (status_.load()) {
    case State::Resting:
      return "resting";
    case State::Done:
      return "done";
    case State::Rendering:
      break;
  }
  return "rendering";
}

bool LiveRender::ShouldWait(const LiveFrame& progress) {
  const bool done = (limits_.seconds > 0.0 && progress.seconds >= limits_.seconds) ||
                    (limits_.spp > 0 && progress.spp >= limits_.spp);
  const bool idle = SecondsSinceAsked() > kIdleSeconds;
  status_ = done ? State::Done : idle ? State::Resting : State::Rendering;
  return done || idle;
}

std::uint64_t LiveRender::Apply(const RenderArgs& args) {
  const std::shared_ptr<const LiveJob> current = Job();
  if (SettingsJson(args) == SettingsJson(current->args)) return current->generation;
  std::shared_ptr<const LiveJob> job = MakeJob(args, current->generation + 1);  // may throw
  CheckReference(job->setup);  // a --set of /camera/resolution may change the size
  const std::lock_guard<std::mutex> lock(mutex_);
  job_ = std::move(job);
  restart_ = true;
  return job_->generation;
}

std::shared_ptr<const LiveJob> LiveRender::Job() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return job_;
}

std::shared_ptr<const LiveFrame> LiveRender::Frame() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return frame_;
}

void LiveRender::Loop() {
  using Clock = std::chrono::steady_clock;
  std::shared_ptr<const LiveJob> job;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<PassLoop> loop;
  const Cluster single;  // this process alone
  LiveFrame progress;    // of the current job: counters and error history
  Clock::time_point start;
  Clock::time_point restBegan;
  bool resting = false;
  int rays = 1;
  while (!stop_) {
    if (job != Job()) {  // (restart_ stays set while resting: it is only a cancel flag)
      restart_ = false;  // the first pass, new settings, or one abandoned
      job = Job();
      const RenderSetup& s = job->setup;
      start = Clock::now();
      resting = false;
      camera = std::make_unique<Camera>(s.scene.wall, s.scene.camera, s.width, s.height);
      PrepareShaftsIfTheyPay(*camera, *job->integrator, s, /*manyPasses=*/true);
      RenderOptions options;
      options.seed = job->args.seed;
      options.sampler = SamplerFromArgs(job->args);
      options.threads = job->setup.threads;
      options.cancel = &restart_;
      loop = std::make_unique<PassLoop>(*camera, *job->integrator, options, single);
      progress = LiveFrame{};
      progress.generation = job->generation;
      rays = job->args.spp > 0 ? job->args.spp : 1;  // --spp: the rays of every pass
    }
    if (ShouldWait(progress)) {  // back to idle until a page asks, or settings change
      if (!resting) restBegan = Clock::now();
      resting = true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    if (resting) start += Clock::now() - restBegan;  // the time axis counts rendering only
    resting = false;
    if (limits_.spp > 0) {  // the last pass takes what is left of the cap
      rays = static_cast<int>(std::min<std::uint64_t>(rays, limits_.spp - progress.spp));
    }
    const PassLoop::Pass pass = loop->Render(rays);
    if (restart_) {  // new settings, or the end: the pass is dropped
      const auto all = static_cast<std::uint64_t>(job->setup.width) *
                       static_cast<std::uint64_t>(job->setup.height) *
                       static_cast<std::uint64_t>(rays);
      abandoned_ += !stop_ && pass.stats.cameraRays < all ? 1 : 0;  // it stopped half-way
      job = nullptr;
      continue;
    }
    loop->Count(pass);
    const double passSeconds = pass.seconds;
    progress.passes = loop->Passes();
    progress.spp = loop->Spp();
    progress.raysTraced += pass.stats.TracedRays();
    progress.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    auto frame = std::make_shared<LiveFrame>(progress);
    // In parallel: the render's threads would otherwise wait for it between passes (at
    // 512x512 one thread took 3% of a 0.25 s pass).
    frame->image = camera->ToImage(job->setup.threads);
    if (reference_) {
      progress.error.push_back({progress.seconds, RelativeMse(frame->image, *reference_)});
      if (progress.error.size() > kMaxErrorPoints) Thin(progress.error);
      frame->error = progress.error;
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      frame->id = ++frames_;
      frame_ = std::move(frame);
    }
    // Doubling up to a pass of about kPassSeconds, halving if a pass ran far over it.
    if (job->args.spp > 0) continue;
    if (passSeconds < 0.5 * kPassSeconds && rays < PassSchedule::kMaxRays) rays *= 2;
    if (passSeconds > 2.0 * kPassSeconds && rays > 1) rays /= 2;
  }
}

}  // namespace glint
