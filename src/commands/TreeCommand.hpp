// `glint tree`: the ray trees of one pixel as a Graphviz graph, showing the design's
// Ray nodes with their kind, the object they hit, importance and colour.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "job/RenderJob.hpp"

namespace glint {

struct TreeArgs {
  RenderArgs render;
  std::string pixel;  // "X,Y"
  std::string output = "tree.dot";
  int maxNodes = 400;
};

int RunTree(const TreeArgs& args);

const char* KindName(RayKind kind);

// The ray trees of pixel (x, y) as the first pass of `glint render` grows them (its
// random numbers), with the pixel's radiance.
struct PixelTrees {
  RayTree trees;
  Colour radiance{0.0};
};
PixelTrees TracePixelTrees(const RenderArgs& args, const RenderSetup& s,
                           const Integrator& integrator, int x, int y);
// The first `maxNodes` nodes: kind, depth, what each hit, W_i, importance, colour and
// the children's indices (`glint view` draws them).
nlohmann::json TreeJson(const RayTree& tree, const Scene& scene, int maxNodes);

}  // namespace glint
