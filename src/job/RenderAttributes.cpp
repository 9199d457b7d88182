#include "job/RenderAttributes.hpp"

#include "glint/core/JsonReader.hpp"
#include "job/Checkpoint.hpp"
#include "job/Revision.hpp"  // generated in the build tree (cmake/Revision.cmake)

namespace glint {

namespace {

// What decides the image a render converges to.
constexpr const char* kSceneFields[] = {"scene_hash", "set", "size", "mode", "walls", "fresnel"};

std::string Quoted(const std::string& s) {
  return "\"" + s + "\"";
}

}  // namespace

ImageAttributes RenderAttributes(const RenderArgs& args, const RenderSetup& s, std::uint64_t spp) {
  std::string set;
  for (const std::string& o : args.overrides) set += (set.empty() ? "" : " ") + o;
  ImageAttributes a = {{"scene", args.scene},
                       {"scene_hash", FileFingerprint(args.scene)},
                       {"set", set},
                       {"size", std::to_string(s.width) + "x" + std::to_string(s.height)},
                       {"mode", args.mode},
                       {"fresnel", args.fresnel},
                       {"sampler", args.sampler},
                       {"spp", std::to_string(spp)},
                       {"seed", std::to_string(args.seed)},
                       {"version", std::string(GLINT_VERSION) + " (revision " GLINT_REVISION ")"}};
  if (args.mode == "mc") a["walls"] = args.walls;
  return a;
}

void CheckSameScene(const ImageAttributes& mine, const ImageAttributes& other,
                    const std::string& otherName, const std::string& mineName) {
  for (const char* field : kSceneFields) {
    const auto m = mine.find(field);
    const auto o = other.find(field);
    if (m == mine.end() || o == other.end() || m->second == o->second) continue;
    std::string name = field;
    if (name == "scene_hash") name = "scene file (contents)";
    if (name == "set") name = "--set";
    const auto scene = other.find("scene");
    throw InputError(otherName + ": a render of another scene or mode: its " + name + " is " +
                     Quoted(name == "scene file (contents)" && scene != other.end()
                                ? scene->second + ", hash " + o->second
                                : o->second) +
                     ", " + mineName + "'s is " + Quoted(m->second));
  }
}

bool SameSeed(const ImageAttributes& a, const ImageAttributes& b) {
  for (const char* field : {"seed", "scene_hash", "sampler"}) {
    const auto x = a.find(field);
    const auto y = b.find(field);
    if (x == a.end() || y == b.end() || x->second != y->second) return false;
  }
  return true;
}

}  // namespace glint
