#include "commands/TreeCommand.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageIO.hpp"
#include "job/ExitCode.hpp"
#include "job/Subprocess.hpp"

namespace glint {

const char* KindName(RayKind kind) {
  switch (kind) {
    case RayKind::Camera:
      return "camera";
    case RayKind::Reflected:
      return "reflected";
    case RayKind::Refracted:
      return "refracted";
    case RayKind::Diffuse:
      return "diffuse";
  }
  return "?";
}

namespace {

const char* KindColour(RayKind kind) {
  switch (kind) {
    case RayKind::Camera:
      return "#dddddd";
    case RayKind::Reflected:
      return "#cfe2ff";
    case RayKind::Refracted:
      return "#d8f5d0";
    case RayKind::Diffuse:
      return "#ffe7c2";
  }
  return "white";
}

std::string Dot(const RayTree& tree, const Scene& scene, int x, int y, int maxNodes) {
  std::string out = "digraph ray_tree {\n  label=\"glint: the ray trees of pixel (" +
                    std::to_string(x) + ", " + std::to_string(y) +
                    "); C_R = L_local + sum W_i C_i\";\n  labelloc=t;\n"
                    "  node [shape=box, style=\"rounded,filled\", fontname=\"Helvetica\", "
                    "fontsize=10];\n  edge [fontname=\"Helvetica\", fontsize=9];\n";
  const int count = std::min<int>(maxNodes, static_cast<int>(tree.Size()));
  char line[512];
  for (int i = 0; i < count; ++i) {
    const Ray& r = tree[static_cast<std::uint32_t>(i)];
    const std::string hit = r.object >= 0 ? scene.ObjectName(r.object) : "nothing (open front)";
    std::snprintf(line, sizeof line,
                  "  n%d [fillcolor=\"%s\", label=\"%s ray, depth %d%s%s\\nhits %s\\nimportance "
                  "%.3g %.3g %.3g\\ncolour %.3g %.3g %.3g\"];\n",
                  i, KindColour(r.kind), KindName(r.kind), r.depth, r.inside ? ", inside" : "",
                  r.final ? ", final" : "", hit.c_str(), r.importance.x, r.importance.y,
                  r.importance.z, r.colour.x, r.colour.y, r.colour.z);
    out += line;
    for (std::uint32_t k = 0; k < r.childCount; ++k) {
      const std::uint32_t c = r.firstChild + k;
      if (static_cast<int>(c) >= count) continue;
      std::snprintf(line, sizeof line, "  n%d -> n%u [label=\"W %.3g %.3g %.3g\"];\n", i, c,
                    tree[c].weight.x, tree[c].weight.y, tree[c].weight.z);
      out += line;
    }
  }
  if (count < static_cast<int>(tree.Size())) {
    out += "  more [shape=plaintext, label=\"... " + std::to_string(tree.Size() - count) +
           " more nodes (--max-nodes)\"];\n";
  }
  return out + "}\n";
}

}  // namespace

PixelTrees TracePixelTrees(const RenderArgs& args, const RenderSetup& s,
                           const Integrator& integrator, int x, int y) {
  const Camera camera(s.scene.wall, s.scene.camera, s.width, s.height);
  // The same random numbers as pixel (x, y) of the first pass of `glint render`.
  const auto index = static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(s.width) +
                     static_cast<std::uint64_t>(x);
  const int rays = args.spp > 0 ? args.spp : 1;
  Sampler sampler(SamplerFromArgs(args), args.seed, index, 0, 0, rays);
  PixelTrees out;
  RenderStats stats;
  Pixel pixel;
  pixel.Render(camera, x, y, rays, integrator, sampler, out.trees, stats, /*keepTrees=*/true);
  out.radiance = pixel.Radiance();
  return out;
}

nlohmann::json TreeJson(const RayTree& tree, const Scene& scene, int maxNodes) {
  const auto rgb = [](const Colour& c) { return nlohmann::json::array({c.x, c.y, c.z}); };
  const int count = std::min<int>(maxNodes, static_cast<int>(tree.Size()));
  nlohmann::json nodes = nlohmann::json::array();
  for (int i = 0; i < count; ++i) {
    const Ray& r = tree[static_cast<std::uint32_t>(i)];
    nlohmann::json children = nlohmann::json::array();
    for (std::uint32_t k = 0; k < r.childCount; ++k) {
      if (static_cast<int>(r.firstChild + k) < count) children.push_back(r.firstChild + k);
    }
    nodes.push_back({{"kind", KindName(r.kind)},
                     {"depth", r.depth},
                     {"hit", r.object >= 0 ? scene.ObjectName(r.object) : "nothing (open front)"},
                     {"inside", r.inside},
                     {"final", r.final},
                     {"weight", rgb(r.weight)},
                     {"importance", rgb(r.importance)},
                     {"colour", rgb(r.colour)},
                     {"children", children}});
  }
  return {{"nodes", nodes}, {"total", tree.Size()}};
}

namespace {

// "dot" for Graphviz text, or the image format dot renders to; anything else refused
// (before the rays are traced), as is an image when Graphviz is not installed.
std::string TreeFormat(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".dot" || ext == ".gv") return "dot";
  if (ext != ".png" && ext != ".svg" && ext != ".pdf") {
    throw InputError("-o " + path + ": expected a file name ending in .dot (Graphviz text), " +
                     ".png, .svg or .pdf (drawn by Graphviz), found '" + ext + "'");
  }
  if (!OnPath("dot")) {
    throw InputError("-o " + path + ": drawing the tree needs Graphviz's dot, which is not " +
                     "installed (apt-get install graphviz, or tools/setup.sh); -o " +
                     std::filesystem::path(path).stem().string() + ".dot writes the text");
  }
  return ext.substr(1);
}

// Writes the Graphviz text, or the picture dot draws from it; either way the output
// appears whole or not at all.
void WriteTree(const std::string& path, const std::string& format, const std::string& dot) {
  if (format == "dot") {
    WriteFileAtomically(path, dot);
    return;
  }
  const std::filesystem::path target(path);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  const std::string base = (dir / ("." + target.filename().string())).string();
  const std::string text = base + ".tmp.dot";
  const std::string image = base + ".tmp." + format;
  WriteFileAtomically(text, dot);
  const int code = RunProgram({"dot", "-T" + format, "-o", image, text});
  std::remove(text.c_str());
  if (code != 0) {
    std::remove(image.c_str());
    throw std::runtime_error(path + ": Graphviz's dot failed (exit code " + std::to_string(code) +
                             ")");
  }
  std::filesystem::rename(image, target);
}

}  // namespace

int RunTree(const TreeArgs& a) {
  int x = 0;
  int y = 0;
  if (std::sscanf(a.pixel.c_str(), "%d,%d", &x, &y) != 2) {
    throw InputError("--pixel " + a.pixel + ": expected X,Y, e.g. --pixel 256,300");
  }
  const RenderSetup s = Prepare(a.render, /*checkOutputs=*/false);
  if (x < 0 || y < 0 || x >= s.width || y >= s.height) {
    throw InputError("--pixel " + a.pixel + ": outside the " + std::to_string(s.width) + "x" +
                     std::to_string(s.height) + " image");
  }
  const std::string format = TreeFormat(a.output);
  CheckWritable(a.output);
  const std::unique_ptr<Integrator> integrator = MakeIntegrator(a.render, s);
  const PixelTrees p = TracePixelTrees(a.render, s, *integrator, x, y);
  WriteTree(a.output, format, Dot(p.trees, s.scene, x, y, a.maxNodes));
  const Colour c = p.radiance;
  std::fprintf(stderr,
               "glint tree: pixel (%d, %d): %zu ray nodes, radiance %.4g %.4g %.4g; wrote %s\n", x,
               y, p.trees.Size(), c.x, c.y, c.z, a.output.c_str());
  return kExitOk;
}

}  // namespace glint
