#include "commands/ViewSettings.hpp"

#include <algorithm>
#include <cstdio>

#include <httplib.h>

#include "glint/core/JsonReader.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"

namespace glint {

namespace {

std::string Join(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  }
  return out;
}

// One of `allowed`, or an InputError in the command line's words.
std::string Choice(const std::string& key, const std::string& value,
                   const std::vector<std::string>& allowed) {
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
  throw InputError("--" + key + " " + value + ": expected " + Join(allowed));
}

long WholeNumber(const std::string& key, const std::string& value, long low, long high) {
  const bool digits = !value.empty() && value.size() <= 18 &&
                      value.find_first_not_of("0123456789") == std::string::npos;
  const long v = digits ? std::stol(value) : -1;
  if (v < low || v > high) {
    throw InputError("--" + key + " " + value + ": expected a whole number in [" +
                     std::to_string(low) + ", " + std::to_string(high) + "]");
  }
  return v;
}

}  // namespace

QueryParams ParseQuery(const std::string& text) {
  QueryParams out;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('&', begin);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(begin, end - begin);
    if (!item.empty()) {
      const std::size_t eq = item.find('=');
      const std::string key = item.substr(0, eq);
      const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
      out.emplace_back(httplib::detail::decode_url(key, true),
                       httplib::detail::decode_url(value, true));
    }
    begin = end + 1;
  }
  return out;
}

RenderArgs ArgsFromQuery(const RenderArgs& base, const QueryParams& query) {
  RenderArgs args = base;
  args.monteCarloSwitches.clear();
  bool sets = false;
  for (const auto& [key, value] : query) {
    if (key == "mode") {
      args.mode = Choice(key, value, kModes);
    } else if (key == "walls") {
      args.walls = Choice(key, value, kWallModes);
    } else if (key == "strategy") {
      args.strategy = Choice(key, value, kStrategies);
    } else if (key == "glass") {
      args.glass = Choice(key, value, kGlassModes);
    } else if (key == "mirror-light") {
      args.mirrorLight = Choice(key, value, kMirrorLightModes);
    } else if (key == "caustics") {
      args.caustics = Choice(key, value, kCausticsModes);
    } else if (key == "branches") {
      args.branches =
          static_cast<int>(WholeNumber(key, value, 1, MonteCarloIntegrator::kMaxBranches));
    } else if (key == "fresnel") {
      args.fresnel = Choice(key, value, kFresnelModels);
    } else if (key == "sampler") {
      args.sampler = Choice(key, value, kSamplers);
    } else if (key == "seed") {
      args.seed = static_cast<std::uint64_t>(WholeNumber(key, value, 0, 1L << 62));
    } else if (key == "set") {
      if (!sets) args.overrides.clear();
      sets = true;
      if (!value.empty()) args.overrides.push_back(value);
    } else if (key != "exposure") {
      throw InputError(
          "unknown setting '" + key +
          "': expected mode, walls, strategy, glass, mirror-light, caustics, branches, fresnel, "
          "sampler, "
          "seed, set or exposure");
    }
    for (const char* name : kMonteCarloSwitches) {
      if (std::string("--") + key == name) args.monteCarloSwitches.emplace_back(name);
    }
  }
  return args;
}

nlohmann::json SettingsJson(const RenderArgs& args) {
  return {{"mode", args.mode},
          {"walls", args.walls},
          {"strategy", args.strategy},
          {"glass", args.glass},
          {"mirror-light", args.mirrorLight},
          {"caustics", args.caustics},
          {"branches", args.branches},
          {"fresnel", args.fresnel},
          {"sampler", args.sampler},
          {"seed", args.seed},
          {"set", args.overrides}};
}

nlohmann::json Tunables(const nlohmann::json& document, double viewPlaneDistance) {
  nlohmann::json out = nlohmann::json::array();
  const auto add = [&](const std::string& pointer, const std::string& label, double value,
                       double low, double high, double step, const char* modes, bool grey = false) {
    out.push_back({{"pointer", pointer},
                   {"label", label},
                   {"value", value},
                   {"min", low},
                   {"max", high},
                   {"step", step},
                   {"modes", modes},
                   {"grey", grey}});
  };
  // A grey value stands for an RGB triple (the page sets all three; "grey": true).
  const auto grey = [](const nlohmann::json& rgb) {
    return rgb.is_array() && rgb.size() == 3 && rgb[0].is_number() ? rgb[0].get<double>() : 0.0;
  };
  const nlohmann::json& objects = document.value("objects", nlohmann::json::array());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const nlohmann::json& o = objects[i];
    const std::string id = o.value("id", "object " + std::to_string(i));
    const std::string at = "/objects/" + std::to_string(i);
    const std::string material = o.value("material", "");
    if (material == "glass" && o.contains("ior") && o["ior"].is_number()) {
      add(at + "/ior", id + " refractive index", o["ior"].get<double>(), 1.0, 2.5, 0.01, "both");
    }
    if (material == "phong" && o.contains("exponent") && o["exponent"].is_number()) {
      add(at + "/exponent", id + " Phong exponent", o["exponent"].get<double>(), 1.0, 1000.0, 1.0,
          "both");
    }
  }
  if (document.contains("area_light") && document["area_light"].contains("radiance")) {
    add("/area_light/radiance", "area light radiance (grey)",
        grey(document["area_light"]["radiance"]), 0.0, 200.0, 0.5, "mc", true);
  }
  // The design's second way to change the perspective: the view plane nearer or farther
  // (its size kept), from the distance the camera uses now.
  add("/camera/view_plane_distance", "view plane distance (m)", viewPlaneDistance, 0.2, 6.0, 0.05,
      "both");
  const nlohmann::json& lights = document.value("point_lights", nlohmann::json::array());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const std::string id = lights[i].value("id", "point light " + std::to_string(i));
    add("/point_lights/" + std::to_string(i) + "/intensity", id + " intensity (grey)",
        grey(lights[i].value("intensity", nlohmann::json())), 0.0, 5.0, 0.05, "whitted", true);
  }
  return out;
}

}  // namespace glint
