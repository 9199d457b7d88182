// The settings of `glint view` as a URL query, `?mode=whitted&set=/objects/1/ior=1.3`:
// the same names and values as the command line's switches (--mode, --walls, --set, ...),
// checked the same way, so that a page's state can be bookmarked and shared.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "job/RenderJob.hpp"

namespace glint {

using QueryParams = std::vector<std::pair<std::string, std::string>>;

// "a=1&set=/objects/1/ior=1.3" into pairs, each split at its first '=' and URL-decoded.
QueryParams ParseQuery(const std::string& text);

// `base` (the command line's) with the query's values in place of its own. Keys: mode,
// walls, strategy, glass, mirror-light, branches, fresnel, sampler, seed, set (repeatable; when
// given, the list replaces the command line's --set) and exposure (the page's own, ignored). A
// Monte Carlo switch with mode=whitted is refused, as on the command line (Prepare). Throws
// InputError naming the setting, what was expected and what was found.
RenderArgs ArgsFromQuery(const RenderArgs& base, const QueryParams& query);

// The settings the page shows: every key above but exposure.
nlohmann::json SettingsJson(const RenderArgs& args);

// Scene values the page offers sliders for, by JSON pointer: each glass object's
// refractive index, each Phong exponent, the area light's radiance (mc) and the point
// lights' intensities (whitted); each with its value in `document` and a range.
nlohmann::json Tunables(const nlohmann::json& document, double viewPlaneDistance);

}  // namespace glint
