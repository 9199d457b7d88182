// The background render of `glint view`: passes over the Camera, one after another, with
// the same integrators and samplers as `glint render`, until stopped. New settings
// abandon the pass in flight (its cancel flag) and start the accumulation again. After
// each pass a frame (the linear image and its counters) is published for the server.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "glint/image/Image.hpp"
#include "job/RenderJob.hpp"

namespace glint {

// What one set of settings renders: checked, with its integrator, never changed after.
struct LiveJob {
  RenderArgs args;
  RenderSetup setup;
  // The scene file with the settings' --set applied (the page saves it; `glint render`
  // reads it back), and the scene values the page offers sliders for (Tunables).
  nlohmann::json document;
  nlohmann::json tunables;
  std::unique_ptr<Integrator> integrator;
  std::uint64_t generation = 0;  // 1, 2, ...: one more for each change of settings
};

// Linear radiance as the page takes it, row 0 first, in Ward's RGBE (4 bytes a pixel: a
// mantissa per channel and a shared exponent, about 1% precision): a third of the bytes
// of float32, and most of the browser's work is receiving them (BENCHMARKS.md).
std::string RgbePixels(const Image& image);

// The image after a pass and what it took.
struct LiveFrame {
  std::uint64_t id = 0;  // counts frames across generations
  std::uint64_t generation = 0;
  Image image;
  std::uint32_t passes = 0;
  std::uint64_t spp = 0;         // rays per pixel accumulated
  double seconds = 0.0;          // since this generation began, its set-up included
  std::uint64_t raysTraced = 0;  // RenderStats::TracedRays of all its passes
  // (seconds, relative MSE against the reference) after each pass, when there is one.
  std::vector<std::array<double, 2>> error;
};

// When the accumulation stops by itself (0: never).
struct LiveLimits {
  double seconds = 0.0;   // --time: of rendering, set-up included
  std::uint64_t spp = 0;  // --max-spp: rays per pixel
};

class LiveRender {
 public:
  // With no page asking for a frame for this long, rendering pauses (the process goes
  // back to idle) until one asks again.
  static constexpr double kIdleSeconds = 10.0;

  // A pass is made to last about this long (rays per pixel double up to it): several
  // frames a second, yet long enough that a pass's set-up costs little (BENCHMARKS.md).
  static constexpr double kPassSeconds = 0.25;

  // Starts rendering `args` at once; throws InputError for bad settings.
  LiveRender(const RenderArgs& args, std::optional<Image> reference, LiveLimits limits = {});
  ~LiveRender();
  LiveRender(const LiveRender&) = delete;
  LiveRender& operator=(const LiveRender&) = delete;

  // Checks `args` and, if they differ from the current ones, restarts with them; throws
  // InputError (the render goes on with the old settings). Returns the generation.
  std::uint64_t Apply(const RenderArgs& args);
  // Throws InputError if `args` would not render; changes nothing.
  static void Check(const RenderArgs& args);
  // A page asked for the state or a frame: rendering goes on (or resumes).
  void Asked();
  // "rendering", "resting" (no page asked for kIdleSeconds) or "done" (a limit reached).
  std::string Status() const;
  std::shared_ptr<const LiveJob> Job() const;
  std::shared_ptr<const LiveFrame> Frame() const;  // null before the first pass
  const std::optional<Image>& Reference() const { return reference_; }
  // Passes that new settings stopped half-way (their camera rays were not all traced).
  std::uint64_t Abandoned() const { return abandoned_.load(); }
  void Stop();

 private:
  static std::shared_ptr<const LiveJob> MakeJob(const RenderArgs& args, std::uint64_t generation);
  // Refuses a render whose size is not the reference's.
  void CheckReference(const RenderSetup& s) const;
  void Loop();

  // Whether the loop should wait before the next pass, and says why in status_.
  bool ShouldWait(const LiveFrame& progress);
  double SecondsSinceAsked() const;

  std::optional<Image> reference_;
  LiveLimits limits_;
  std::atomic<std::int64_t> lastAsked_;  // steady clock, nanoseconds
  enum class State { Rendering, Resting, Done };
  std::atomic<State> status_{State::Rendering};
  mutable std::mutex mutex_;
  std::shared_ptr<const LiveJob> job_;
  std::shared_ptr<const LiveFrame> frame_;
  std::uint64_t frames_ = 0;
  std::atomic<bool> restart_{false};  // the cancel flag of the pass in flight
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> abandoned_{0};
  std::thread thread_;
};

}  // namespace glint
