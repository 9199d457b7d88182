// Scene files: JSON, validated field by field (see scenes/cornell.json), with
// command-line overrides by JSON pointer (`/objects/1/ior=1.3`).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glint/core/JsonReader.hpp"
#include "glint/scene/Scene.hpp"

namespace glint {

// Parses the file; a syntax error becomes an InputError with file:line:column.
nlohmann::json ReadJsonFile(const std::string& path);
// The same for text already in memory; `name` stands for the file in messages.
nlohmann::json ParseJsonText(const std::string& text, const std::string& name);

// Applies one "POINTER=VALUE" override. VALUE is read as JSON, or as a string if it is
// not JSON. The pointer's parent must exist in the document.
void ApplyOverride(nlohmann::json& document, const std::string& assignment,
                   const std::string& file);

// Builds and validates a scene; every error is an InputError naming the field.
Scene SceneFromJson(const nlohmann::json& document, const std::string& file);

// ReadJsonFile, then the overrides in order: the document a scene is built from.
nlohmann::json LoadSceneDocument(const std::string& path,
                                 const std::vector<std::string>& overrides = {});

// LoadSceneDocument, then SceneFromJson.
Scene LoadScene(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace glint
