// libFuzzer target for the scene loader: any bytes must end in a scene or an InputError,
// never a crash, a hang, an uncaught exception or undefined behaviour. A scene that
// loads is also rendered at 4x4 in both modes: validated input must render safely.
#include <cstddef>
#include <cstdint>
#include <string>

#include "glint/camera/Camera.hpp"
#include "glint/scene/SceneLoader.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/WhittedIntegrator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace glint;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene = SceneFromJson(ParseJsonText(text, "fuzz.json"), "fuzz.json");
    Camera camera(scene.wall, scene.camera, 4, 4);
    RenderOptions options;
    options.threads = 1;
    camera.Render(WhittedIntegrator(scene, scene.whitted.maxDepth), options);
    if (scene.light) {
      MonteCarloOptions mc;
      mc.maxDepth = scene.mc.maxDepth;
      mc.walls = MonteCarloOptions::Walls::Diffuse;
      camera.Render(MonteCarloIntegrator(scene, mc), options);
    }
  } catch (const InputError&) {
  } catch (const std::invalid_argument&) {  // e.g. a camera the set-up rule cannot place
  }
  return 0;
}
