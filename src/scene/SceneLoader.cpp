#include "glint/scene/SceneLoader.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

#include "glint/core/Format.hpp"

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

// The fields a material may have. One rule for all: a field the material does not use is
// refused, with the reason, rather than accepted and ignored.
struct MaterialFields {
  const char* name;
  std::initializer_list<const char*> uses;
  const char* without;  // why the others mean nothing to it
};

const MaterialFields kMaterials[] = {
    {"phong",
     {"reflectance", "exponent", "whitted_diffuse", "whitted_specular"},
     "only glass refracts"},
    {"mirror",
     {"reflectance", "exponent", "whitted_diffuse", "whitted_specular"},
     "only glass refracts"},
    {"glass",
     {"ior", "exponent", "whitted_diffuse", "whitted_specular"},
     "glass is clear: Fresnel's equations give what it reflects and transmits"},
    {"lambertian", {"reflectance"}, "it reflects rho/pi, as a wall, and has no highlight"},
};

void RejectFieldsUnusedBy(const JsonReader& o, const std::string& kind) {
  for (const MaterialFields& m : kMaterials) {
    if (kind != m.name) continue;
    for (const char* key :
         {"reflectance", "exponent", "ior", "whitted_diffuse", "whitted_specular"}) {
      if (!o.Has(key)) continue;
      if (std::find_if(m.uses.begin(), m.uses.end(),
                       [&](const char* k) { return std::string(k) == key; }) != m.uses.end()) {
        continue;
      }
      o.Refuse(key, std::string("material \"") + m.name + "\" has no field \"" + key + "\" (" +
                        m.without + "): delete it (with --set: " + o.PathOf(key) + "=null)");
    }
  }
}

Material ReadObjectMaterial(const JsonReader& o) {
  Material m;
  const std::string kind = o.String("material", {"phong", "mirror", "glass", "lambertian"});
  RejectFieldsUnusedBy(o, kind);
  if (kind == "lambertian") {
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
           FormatNumber(m.whittedDiffuse) + " + " + FormatNumber(m.whittedSpecular));
  }
  return m;
}

// Every part of the scene has a name (its id, or a default) that messages and
// `glint tree` use: two parts with one name would make both ambiguous.
class SceneNames {
 public:
  explicit SceneNames(Scene& scene) : scene_(scene) {}

  void Add(const JsonReader& r, const std::string& fallback) {
    const bool given = r.Has("id");
    const std::string name = given ? r.Text("id") : fallback;
    const auto it = where_.find(name);
    if (it != where_.end()) {
      r.Fail("id", "an id that no other part of the scene has",
             (given ? "\"" + name + "\"" : "nothing, and the default \"" + name + "\"") +
                 ", already the id of " + it->second);
    }
    AddFixed(name, r.Path());
  }
  void AddFixed(const std::string& name, const std::string& path) {
    where_.emplace(name, path.empty() ? "/" : path);
    scene_.objectNames.push_back(name);
  }
  // The object index the next part gets.
  int Next() const { return static_cast<int>(scene_.objectNames.size()); }

 private:
  Scene& scene_;
  std::map<std::string, std::string> where_;
};

void ReadRoom(const JsonReader& root, Scene& scene, SceneNames& names) {
  const JsonReader room = root.Object("room");
  room.RejectUnknownKeys({"position", "size", "walls"});
  const vec3 position = room.Vec3("position", kCoordinate);
  const double size = room.Number("size", kLength);
  const std::vector<JsonReader> walls = room.Objects("walls", Wall::kSides, Wall::kSides);
  std::array<Material, Wall::kSides> materials;
  for (int i = 0; i < Wall::kSides; ++i) {
    const JsonReader& w = walls[static_cast<std::size_t>(i)];
    w.RejectUnknownKeys({"id", "side", "reflectance"});
    const nlohmann::json& side = w.Json().contains("side") ? w.Json()["side"] : nlohmann::json();
    if (!side.is_string() || side.get<std::string>() != kSideNames[i]) {
      w.Fail("side",
             std::string("\"") + kSideNames[i] + "\" (wall " + std::to_string(i + 1) +
                 "; the walls come in the fixed order left, ceiling, right, floor, back)",
             w.Has("side") ? DescribeJson(side) : "nothing");
    }
    materials[static_cast<std::size_t>(i)].type = MaterialType::Lambertian;
    materials[static_cast<std::size_t>(i)].reflectance =
        w.Vec3("reflectance", Range::Closed(0.0, 1.0));
    materials[static_cast<std::size_t>(i)].whittedDiffuse = 1.0;  // rho / pi * E
    names.Add(w, "W" + std::to_string(i + 1));
  }
  scene.wall = Wall(position, size, materials, 0);
}

// "[0, 1]" for the room's extent along one axis.
std::string RoomInterval(const Wall& room, int axis) {
  return "[" + FormatNumber(room.Position()[axis]) + ", " +
         FormatNumber(room.Position()[axis] + room.Size()) + "]";
}

void RequireInsideRoom(const Scene& scene, const JsonReader& r, const char* key, const char* what,
                       vec3 lo, vec3 hi) {
  const double eps = 1e-9 * (1.0 + scene.wall.Size());
  if (!scene.wall.Contains(lo, eps) || !scene.wall.Contains(hi, eps)) {
    const std::string extent =
        lo == hi ? "at " + FormatPoint(lo) : "from " + FormatPoint(lo) + " to " + FormatPoint(hi);
    r.Fail(key, std::string(what) + " inside the room " + RoomInterval(scene.wall, 0) + "^3",
           "one " + extent);
  }
}

void ReadObjects(const JsonReader& root, Scene& scene, SceneNames& names) {
  for (const JsonReader& o : root.Objects("objects", 0, 64)) {
    const std::string type = o.String("type", {"sphere", "cube"});
    const int id = names.Next();
    names.Add(o, "O" + std::to_string(id - 4));
    if (type == "sphere") {
      o.RejectUnknownKeys({"id", "type", "center", "radius", "material", "reflectance", "exponent",
                           "ior", "whitted_diffuse", "whitted_specular"});
      const vec3 centre = o.Vec3("center", kCoordinate);
      const double radius = o.Number("radius", kLength);
      RequireInsideRoom(scene, o, "center", "a sphere", centre - vec3(radius),
                        centre + vec3(radius));
      scene.spheres.emplace_back(centre, radius, ReadObjectMaterial(o), id);
    } else {
      o.RejectUnknownKeys({"id", "type", "position", "size", "material", "reflectance", "exponent",
                           "ior", "whitted_diffuse", "whitted_specular"});
      const vec3 position = o.Vec3("position", kCoordinate);
      const double size = o.Number("size", kLength);
      RequireInsideRoom(scene, o, "position", "a cube", position, position + vec3(size));
      scene.cubes.emplace_back(position, size, ReadObjectMaterial(o), id);
    }
  }
}

void ReadAreaLight(const JsonReader& root, Scene& scene, SceneNames& names) {
  const JsonReader a = root.Object("area_light");
  a.RejectUnknownKeys({"center", "side", "radiance"});
  const vec3 centre = a.Vec3("center", kCoordinate);
  const double side = a.Number("side", kLength);
  const Colour radiance = a.Vec3("radiance", Range::AtLeast(0.0));
  const double ceiling = scene.wall.Position().y + scene.wall.Size();
  if (std::abs(centre.y - ceiling) > 1e-9 * (1.0 + scene.wall.Size())) {
    a.Fail("center", "a point in the ceiling plane y = " + FormatNumber(ceiling),
           "y = " + FormatNumber(centre.y));
  }
  const vec3 corner = centre - vec3(0.5 * side, 0.0, 0.5 * side);
  const vec3 far = corner + vec3(side, 0.0, side);
  const double eps = 1e-9 * (1.0 + scene.wall.Size());
  if (!scene.wall.Contains(corner, eps) || !scene.wall.Contains(far, eps)) {
    a.Fail("side",
           "a light inside the ceiling, x in " + RoomInterval(scene.wall, 0) + " and z in " +
               RoomInterval(scene.wall, 2),
           "one with x from " + FormatComputed(corner.x) + " to " + FormatComputed(far.x) +
               " and z from " + FormatComputed(corner.z) + " to " + FormatComputed(far.z));
  }
  // Edges x then z: normalize(x cross z) = -y, emitting downward into the room.
  const int id = names.Next();
  names.AddFixed("L", a.Path());
  scene.light.emplace(Rectangle(corner, vec3(side, 0.0, 0.0), vec3(0.0, 0.0, side)), radiance, id);
}

void ReadLights(const JsonReader& root, Scene& scene, SceneNames& names) {
  if (root.Has("area_light")) ReadAreaLight(root, scene, names);
  if (!root.Has("point_lights")) return;
  int n = 0;
  for (const JsonReader& p : root.Objects("point_lights", 0, 16)) {
    p.RejectUnknownKeys({"id", "position", "intensity"});
    PointLight light;
    light.position = p.Vec3("position", kCoordinate);
    light.intensity = p.Vec3("intensity", Range::AtLeast(0.0));
    RequireInsideRoom(scene, p, "position", "a point light", light.position, light.position);
    light.object = names.Next();
    names.Add(p, "P" + std::to_string(++n));
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

namespace {

// The first byte at or after `from` that is not white space, or text.size().
std::size_t SkipSpace(const std::string& text, std::size_t from) {
  while (from < text.size() && std::isspace(static_cast<unsigned char>(text[from])) != 0) ++from;
  return from;
}

// The first byte outside JSON strings for which found(i) holds, or npos.
template <class Found>
std::size_t FindOutsideStrings(const std::string& text, Found found) {
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') {
        ++i;  // an escaped character, perhaps a quote
      } else if (c == '"') {
        inString = false;
      }
    } else if (c == '"') {
      inString = true;
    } else if (found(i)) {
      return i;
    }
  }
  return std::string::npos;
}

// The first comment (// or /*): JSON has none, but people write them.
std::size_t FindComment(const std::string& text) {
  return FindOutsideStrings(text, [&](std::size_t i) {
    return text[i] == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*');
  });
}

// The first comma followed (after white space) by '}' or ']'.
std::size_t FindTrailingComma(const std::string& text) {
  return FindOutsideStrings(text, [&](std::size_t i) {
    const std::size_t next = SkipSpace(text, i + 1);
    return text[i] == ',' && next < text.size() && (text[next] == '}' || text[next] == ']');
  });
}

}  // namespace

nlohmann::json ParseJsonText(const std::string& text, const std::string& name) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    // The two mistakes people make most: a comment, and a comma after the last element.
    // Each is reported where it is, if it comes before the parser gave up.
    const std::size_t comment = FindComment(text);
    const std::size_t comma = FindTrailingComma(text);
    if (comment != std::string::npos && comment <= offset &&
        (comma == std::string::npos || comment < comma)) {
      throw InputError(name + ":" + LineColumn(text, comment) +
                       ": a comment, and JSON has none: delete it (the \"description\" field "
                       "holds free text)");
    }
    if (comma != std::string::npos && comma <= offset) {
      throw InputError(name + ":" + LineColumn(text, comma) +
                       ": a comma after the last element of a list or object, which JSON does "
                       "not allow: delete it");
    }
    // Otherwise nlohmann's own words, which read "[json.exception.parse_error.101] parse
    // error at line 3, column 5: syntax error ..."; keep the part after the position.
    const std::string what = e.what();
    const std::size_t colon = what.find(": ", what.find("parse error"));
    const std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
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
    // null removes a field: the way to drop one that a new material refuses
    // (--set /objects/2/material=glass --set /objects/2/reflectance=null).
    if (value.is_null() && parent.is_object()) {
      parent.erase(ptr.back());
    } else {
      document[ptr] = value;
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file + ": --set " + pointer + ": not a valid JSON pointer (" + e.what() + ")");
  }
}

Scene SceneFromJson(const nlohmann::json& document, const std::string& file) {
  const JsonReader root(document, file, "");
  root.RejectUnknownKeys(
      {"description", "room", "objects", "area_light", "point_lights", "camera", "whitted", "mc"});
  Scene scene;
  SceneNames names(scene);
  ReadRoom(root, scene, names);
  ReadObjects(root, scene, names);
  ReadLights(root, scene, names);

  const JsonReader camera = root.Object("camera");
  camera.RejectUnknownKeys({"eye", "view_plane_distance", "resolution"});
  scene.camera.eye = camera.Vec3("eye", kCoordinate);
  scene.camera.viewPlaneDistance = camera.NumberOr("view_plane_distance", 0.0, kLength);
  const vec3 back = scene.wall.Centre() - vec3(0.0, 0.0, 0.5 * scene.wall.Size());
  const double front = scene.wall.Position().z + scene.wall.Size();
  const vec3 eye = scene.camera.eye;
  if (!scene.wall.EyeOnAxis(eye)) {
    camera.Fail("eye",
                "a point on the axis of the back wall in front of the room, (" +
                    FormatNumber(back.x) + ", " + FormatNumber(back.y) + ", z > " +
                    FormatNumber(front) + ")",
                FormatPoint(eye));
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
