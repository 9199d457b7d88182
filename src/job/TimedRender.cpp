#include "job/TimedRender.hpp"

#include <utility>

namespace glint {

TimedRender PrepareTimedRender(RenderSetup setup, const RenderArgs& args) {
  TimedRender t;
  t.setup = std::make_unique<RenderSetup>(std::move(setup));
  const RenderSetup& s = *t.setup;
  t.camera = std::make_unique<Camera>(s.scene.wall, s.scene.camera, s.width, s.height);
  t.integrator = MakeIntegrator(args, s);
  t.options.seed = args.seed;
  t.options.sampler = SamplerFromArgs(args);
  t.options.threads = args.threads;
  t.options.raysPerPixel = 1;
  t.options.pass = 0xffffffffU;  // the warm-up's own streams
  t.camera->Render(*t.integrator, t.options);
  t.options.pass = 0;
  return t;
}

}  // namespace glint
