// `glint tree`: the ray trees of one pixel as a Graphviz graph, showing the design's
// Ray nodes with their kind, the object they hit, importance and colour.
#pragma once

#include <string>

#include "RenderJob.hpp"

namespace glint {

struct TreeArgs {
  RenderArgs render;
  std::string pixel;  // "X,Y"
  std::string output = "tree.dot";
  int maxNodes = 400;
};

int RunTree(const TreeArgs& args);

}  // namespace glint
