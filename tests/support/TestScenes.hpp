// Scenes and paths shared by the tests.
#pragma once

#include <string>

#include "glint/scene/SceneLoader.hpp"

namespace glint::testing {

inline std::string SourcePath(const std::string& relative) {
  return std::string(GLINT_SOURCE_DIR) + "/" + relative;
}
inline std::string BinaryPath(const std::string& relative) {
  return std::string(GLINT_BINARY_DIR) + "/" + relative;
}

inline Scene CanonicalScene(const std::vector<std::string>& overrides = {}) {
  return LoadScene(SourcePath("scenes/cornell.json"), overrides);
}

}  // namespace glint::testing
