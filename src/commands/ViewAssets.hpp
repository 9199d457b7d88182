// The page of `glint view` (src/commands/view/), compiled into the binary: the server has its
// assets without reading any file, and works wherever glint is copied.
#pragma once

#include <string_view>
#include <vector>

namespace glint {

struct ViewAsset {
  const char* path;  // the URL path, e.g. "/view.js"
  const char* type;  // its Content-Type
  std::string_view body;
};

// Generated at build time by cmake/EmbedAssets.cmake.
const std::vector<ViewAsset>& ViewAssets();

}  // namespace glint
