#include "glint/scene/SceneLoader.hpp"

#include <fstream>
#include <sstream>

namespace glint {

namespace {

// Coordinates and lengths: generous, but far from where double arithmetic overflows.
const Range kCoordinate = Range::Closed(-1e6, 1e6);
const Range kLength = {0.0, 1e6, true, false};

constexpr const char* kSideNames[Wall::kSides] = {"left", "ceiling", "right", "floor", "back"};

// Where byte `offset` of `text` lies, as "line:column" (both from 1).
std::string LineColumn(const std::string& text, std::size_t offset) {
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

Material ReadObjectMaterial(const JsonReader& o) {
  Material m;
  const std::string kind = o.String("material", {"phong", "mirror", "glass", "lambertian"});
  if (kind == "lambertian") {
    // The walls' BRDF rho / pi, lit directly in Whitted mode as a wall is: it has no
    // exponent and no Whitted weights of its own.
    for (const char* key : {"exponent", "ior", "whitted_diffuse", "whitted_specular"}) {
      if (o.Has(key)) {
        o.Fail(key, "no such field with material \"lambertian\" (it reflects rho/pi, as a wall)",
               DescribeJson(o.Json()[key]));
      }
    }
    m.type = MaterialType::Lambertian;
    m.reflectance = o.Vec3("reflectance", Range::Closed(0.0, 1.0));
    m.whittedDiffuse = 1.0;  // rho / pi * E, as a wall
    return m;
  }
  if (kind == "glass") {
    m.type = MaterialType::Glass;
    m.ior = o.Number("ior", Range::AtLeast(1.0));
    m.reflectance = Colour(1.0);  // the colour of its Phong highlight
    m.exponent = o.NumberOr("exponent", 100.0, Range::AtLeast(0.0));
  } else {
    m.type = kind == "mirror" ? MaterialType::Mirror : MaterialType::Phong;
    m.reflectance = o.Vec3("reflectance", Range::Closed(0.0, 1.0));
    m.exponent = kind == "mirror" ? o.NumberOr("exponent", 100.0, Range::AtLeast(0.0))
                                  : o.Number("exponent", Range::AtLeast(0.0));
  }
  m.whittedDiffuse = o.NumberOr("whitted_diffuse", 0.0, Range::Closed(0.0, 1.0));
  m.whittedSpecular = o.NumberOr("whitted_specular", 0.0, Range::Closed(0.0, 1.0));
  if (m.whittedDiffuse + m.whittedSpecular > 1.0) {
    o.Fail("whitted_specular",
           "whitted_diffuse + whitted_specular <= 1 (the weights of a "
           "node sum to 1)",
           std::to_string(m.whittedDiffuse + m.whittedSpecular));
  }
  return m;
}

void ReadRoom(const JsonReader& root, Scene& scene) {
  const JsonReader room = root.Object("room");
  room.RejectUnknownKeys({"position", "size", "walls"});
  const vec3 position = room.Vec3("position", kCoordinate);
  const double size = room.Number("size", kLength);
  const std::vector<JsonReader> walls = room.Objects("walls", Wall::kSides, Wall::kSides);
  std::array<Material, Wall::kSides> materials;
  for (int i = 0; i < Wall::kSides; ++i) {
    const JsonReader& w = walls[static_cast<std::size_t>(i)];
    w.RejectUnknownKeys({"id", "side", "reflectance"});
    const std::string side = w.String("side", {kSideNames[i]});
    materials[static_cast<std::size_t>(i)].type = MaterialType::Lambertian;
    materials[static_cast<std::size_t>(i)].reflectance =
        w.Vec3("reflectance", Range::Closed(0.0, 1.0));
    materials[static_cast<std::size_t>(i)].whittedDiffuse = 1.0;  // rho / pi * E
    scene.objectNames.push_back(w.Has("id") ? w.Text("id") : "W" + std::to_string(i + 1));
  }
  scene.wall = Wall(position, size, materials, 0);
}

void RequireInsideRoom(const Scene& scene, const JsonReader& r, const char* key, vec3 lo, vec3 hi) {
  const double eps = 1e-9 * (1.0 + scene.wall.Size());
  if (!scene.wall.Contains(lo, eps) || !scene.wall.Contains(hi, eps)) {
    r.Fail(key,
           "an object inside the room [" + std::to_string(scene.wall.Position().x) + ", " +
               std::to_string(scene.wall.Position().x + scene.wall.Size()) + "]^3",
           "one that reaches outside it");
  }
}

void ReadObjects(const JsonReader& root, Scene& scene) {
  for (const JsonReader& o : root.Objects("objects", 0, 64)) {
    const std::string type = o.String("type", {"sphere", "cube"});
    const int id = static_cast<int>(scene.objectNames.size());
    scene.objectNames.push_back(o.Has("id") ? o.Text("id") : "O" + std::to_string(id - 4));
    if (type == "sphere") {
      o.RejectUnknownKeys({"id", "type", "center", "radius", "material", "reflectance", "exponent",
                           "ior", "whitted_diffuse", "whitted_specular"});
      const vec3 centre = o.Vec3("center", kCoordinate);
      const double radius = o.Number("radius", kLength);
      RequireInsideRoom(scene, o, "center", centre - vec3(radius), centre + vec3(radius));
      scene.spheres.emplace_back(centre, radius, ReadObjectMaterial(o), id);
    } else {
      o.RejectUnknownKeys({"id", "type", "position", "size", "material", "reflectance", "exponent",
                           "ior", "whitted_diffuse", "whitted_specular"});
      const vec3 position = o.Vec3("position", kCoordinate);
      const double size = o.Number("size", kLength);
      RequireInsideRoom(scene, o, "position", position, position + vec3(size));
      scene.cubes.emplace_back(position, size, ReadObjectMaterial(o), id);
    }
  }
}

void ReadLights(const JsonReader& root, Scene& scene) {
  if (root.Has("area_light")) {
    const JsonReader a = root.Object("area_light");
    a.RejectUnknownKeys({"center", "side", "radiance"});
    const vec3 centre = a.Vec3("center", kCoordinate);
    const double side = a.Number("side", kLength);
    const Colour radiance = a.Vec3("radiance", Range::AtLeast(0.0));
    const double ceiling = scene.wall.Position().y + scene.wall.Size();
    if (std::abs(centre.y - ceiling) > 1e-9 * (1.0 + scene.wall.Size())) {
      a.Fail("center", "a point in the ceiling plane y = " + std::to_string(ceiling),
             "y = " + std::to_string(centre.y));
    }
    const vec3 corner = centre - vec3(0.5 * side, 0.0, 0.5 * side);
    RequireInsideRoom(scene, a, "side", corner, corner + vec3(side, 0.0, side));
    // Edges x then z: normalize(x cross z) = -y, emitting downward into the room.
    const int id = static_cast<int>(scene.objectNames.size());
    scene.objectNames.emplace_back("L");
    scene.light.emplace(Rectangle(corner, vec3(side, 0.0, 0.0), vec3(0.0, 0.0, side)), radiance,
                        id);
  }
  if (!root.Has("point_lights")) return;
  for (const JsonReader& p : root.Objects("point_lights", 0, 16)) {
    p.RejectUnknownKeys({"id", "position", "intensity"});
    PointLight light;
    light.position = p.Vec3("position", kCoordinate);
    light.intensity = p.Vec3("intensity", Range::AtLeast(0.0));
    RequireInsideRoom(scene, p, "position", light.position, light.position);
    light.object = static_cast<int>(scene.objectNames.size());
    scene.objectNames.push_back(p.Has("id") ? p.Text("id") : "P");
    scene.pointLights.push_back(light);
  }
}

// Squared distance from p to the box [lo, hi].
double DistanceSquaredToBox(vec3 p, vec3 lo, vec3 hi) {
  const vec3 q = glm::clamp(p, lo, hi);
  return glm::dot(p - q, p - q);
}

// Objects that interpenetrate are legal but almost always a typo: warn about them.
// Touching (a sphere resting on a cube) is not an overlap.
void WarnAboutOverlaps(Scene& scene, const std::string& file) {
  const double eps = 1e-9 * (1.0 + scene.wall.Size());
  const auto name = [&](int object) { return scene.ObjectName(object); };
  const auto warn = [&](int a, int b) {
    scene.warnings.push_back(file + ": objects " + name(a) + " and " + name(b) + " overlap");
  };
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    const Sphere& a = scene.spheres[i];
    for (std::size_t j = i + 1; j < scene.spheres.size(); ++j) {
      const Sphere& b = scene.spheres[j];
      if (glm::length(a.Centre() - b.Centre()) < a.Radius() + b.Radius() - eps) {
        warn(a.Object(), b.Object());
      }
    }
    for (const Cube& c : scene.cubes) {
      const double d2 =
          DistanceSquaredToBox(a.Centre(), c.Position(), c.Position() + vec3(c.Size()));
      if (std::sqrt(d2) < a.Radius() - eps) warn(a.Object(), c.Object());
    }
  }
  for (std::size_t i = 0; i < scene.cubes.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.cubes.size(); ++j) {
      const Cube& a = scene.cubes[i];
      const Cube& b = scene.cubes[j];
      const vec3 lo = glm::max(a.Position(), b.Position());
      const vec3 hi = glm::min(a.Position() + vec3(a.Size()), b.Position() + vec3(b.Size()));
      if (hi.x - lo.x > eps && hi.y - lo.y > eps && hi.z - lo.z > eps) {
        warn(a.Object(), b.Object());
      }
    }
  }
}

ModeSettings ReadMode(const JsonReader& root, const char* key, ModeSettings fallback) {
  if (!root.Has(key)) return fallback;
  const JsonReader m = root.Object(key);
  m.RejectUnknownKeys({"spp", "max_depth", "exposure"});
  ModeSettings s;
  s.spp = m.IntegerOr("spp", fallback.spp, Range::Closed(1, 1 << 20));
  s.maxDepth = m.IntegerOr("max_depth", fallback.maxDepth, Range::Closed(1, 64));
  s.exposure = m.NumberOr("exposure", fallback.exposure, Range::Positive());
  return s;
}

}  // namespace

nlohmann::json ParseJsonText(const std::string& text, const std::string& name) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5:
    // syntax error ..."; keep the part after the position.
    const std::string what = e.what();
    const std::size_t colon = what.find(": ", what.find("parse error"));
    const std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
    const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    throw InputError(name + ":" + LineColumn(text, offset) + ": invalid JSON: " + detail);
  } catch (const nlohmann::json::exception& e) {
    // Not a syntax error but still bad input, e.g. "number overflow parsing '1E6817'"
    // (found by the fuzzer). Drop the "[json.exception.out_of_range.406] " prefix.
    const std::string what = e.what();
    const std::size_t bracket = what.find("] ");
    throw InputError(name + ": invalid JSON: " +
                     (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
}

nlohmann::json ReadJsonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the scene file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in.good() && !in.eof()) throw InputError(path + ": cannot read the scene file");
  return ParseJsonText(buffer.str(), path);
}

void ApplyOverride(nlohmann::json& document, const std::string& assignment,
                   const std::string& file) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0 || assignment[0] != '/') {
    throw InputError(file + ": --set " + assignment +
                     ": expected POINTER=VALUE with a JSON pointer, "
                     "for example --set /objects/1/ior=1.3");
  }
  const std::string pointer = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;  // not JSON: a plain string
  try {
    const nlohmann::json::json_pointer ptr(pointer);
    // The deepest part of the pointer that exists, for a message that says what is missing.
    nlohmann::json::json_pointer missing = ptr.parent_pointer();
    while (!document.contains(missing)) {
      nlohmann::json::json_pointer up = missing.parent_pointer();
      if (document.contains(up) && document[up].is_array()) {
        throw InputError(file + ": --set " + pointer + ": no element " + missing.back() +
                         " in the array " + up.to_string() + " (it has " +
                         std::to_string(document[up].size()) + ")");
      }
      if (document.contains(up)) {
        throw InputError(file + ": --set " + pointer + ": the scene has no field " +
                         missing.to_string());
      }
      missing = up;
    }
    nlohmann::json& parent = document[ptr.parent_pointer()];
    if (parent.is_array()) {
      if (!document.contains(ptr)) {
        throw InputError(file + ": --set " + pointer + ": no element " + ptr.back() +
                         " in the array " + ptr.parent_pointer().to_string());
      }
    } else if (!parent.is_object()) {
      throw InputError(file + ": --set " + pointer + ": " + ptr.parent_pointer().to_string() +
                       " is " + DescribeJson(parent) + ", not an object or array");
    }
    document[ptr] = value;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file + ": --set " + pointer + ": not a valid JSON pointer (" + e.what() + ")");
  }
}

Scene SceneFromJson(const nlohmann::json& document, const std::string& file) {
  const JsonReader root(document, file, "");
  root.RejectUnknownKeys(
      {"description", "room", "objects", "area_light", "point_lights", "camera", "whitted", "mc"});
  Scene scene;
  ReadRoom(root, scene);
  ReadObjects(root, scene);
  ReadLights(root, scene);

  const JsonReader camera = root.Object("camera");
  camera.RejectUnknownKeys({"eye", "resolution"});
  scene.camera.eye = camera.Vec3("eye", kCoordinate);
  const vec3 back = scene.wall.Centre() - vec3(0.0, 0.0, 0.5 * scene.wall.Size());
  const double front = scene.wall.Position().z + scene.wall.Size();
  const vec3 eye = scene.camera.eye;
  if (!scene.wall.EyeOnAxis(eye)) {
    camera.Fail("eye",
                "a point on the axis of the back wall in front of the room, (" +
                    std::to_string(back.x) + ", " + std::to_string(back.y) + ", z > " +
                    std::to_string(front) + ")",
                "(" + std::to_string(eye.x) + ", " + std::to_string(eye.y) + ", " +
                    std::to_string(eye.z) + ")");
  }
  if (!camera.Has("resolution")) {
    camera.Fail("resolution", "[width, height] (the field is required)", "nothing");
  }
  const nlohmann::json& res = document.at("camera").at("resolution");
  if (!res.is_array() || res.size() != 2 || !res[0].is_number_integer() ||
      !res[1].is_number_integer() || res[0].get<long long>() < 1 || res[1].get<long long>() < 1 ||
      res[0].get<long long>() > 65536 || res[1].get<long long>() > 65536) {
    camera.Fail("resolution", "[width, height], whole numbers in [1, 65536]", DescribeJson(res));
  }
  scene.camera.width = res[0].get<int>();
  scene.camera.height = res[1].get<int>();

  scene.whitted = ReadMode(root, "whitted", scene.whitted);
  scene.mc = ReadMode(root, "mc", scene.mc);
  if (root.Has("description")) root.Text("description");
  WarnAboutOverlaps(scene, file);
  return scene;
}

nlohmann::json LoadSceneDocument(const std::string& path,
                                 const std::vector<std::string>& overrides) {
  nlohmann::json document = ReadJsonFile(path);
  for (const std::string& o : overrides) ApplyOverride(document, o, path);
  return document;
}

Scene LoadScene(const std::string& path, const std::vector<std::string>& overrides) {
  return SceneFromJson(LoadSceneDocument(path, overrides), path);
}

}  // namespace glint
