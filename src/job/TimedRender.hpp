// A render made ready to be timed again and again (glint bench's rows, glint converge's
// variants): its setup, camera and integrator built once, the setup kept in place (the
// integrator refers to its scene), and one warm-up pass of one ray per pixel rendered
// outside any clock (threads started, arenas grown, pages touched).
#pragma once

#include <memory>

#include "glint/camera/Camera.hpp"
#include "glint/camera/Integrator.hpp"
#include "job/RenderSetup.hpp"

namespace glint {

struct TimedRender {
  std::unique_ptr<RenderSetup> setup;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<Integrator> integrator;
  RenderOptions options;  // the args' seed, sampler and threads; pass 0
};

// `setup` is Prepare(args, ...)'s, already checked by the caller.
TimedRender PrepareTimedRender(RenderSetup setup, const RenderArgs& args);

}  // namespace glint
