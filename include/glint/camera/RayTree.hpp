// Storage for the ray trees of one pixel. Nodes live in one array and refer to their
// children by index, so a tree is built without a heap allocation per ray: the array
// is cleared (keeping its capacity) before every pixel and reused by the thread that
// renders it.
#pragma once

#include <cstdint>
#include <vector>

#include "glint/camera/Ray.hpp"

namespace glint {

// Aligned to a cache line: the Camera keeps one arena per thread side by side, and
// every ray writes its arena's end pointer (false sharing cost 40% at 2 threads).
class alignas(64) RayTree {
 public:
  RayTree() { nodes_.reserve(4096); }

  void Clear() { nodes_.clear(); }

  std::uint32_t Add(const Ray& ray) {
    nodes_.push_back(ray);
    return static_cast<std::uint32_t>(nodes_.size() - 1);
  }

  // Appends `count` default children to `parent` and returns the first one's index.
  // Children are appended in one block, so [first, first + count) are siblings.
  std::uint32_t AddChildren(std::uint32_t parent, std::uint32_t count) {
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.resize(nodes_.size() + count);
    nodes_[parent].firstChild = first;
    nodes_[parent].childCount = count;
    return first;
  }

  // For trees built breadth-first or in lock-step, whose nodes [first, Size()) hold their
  // local light as their colour: adds each node's children's W_i C_i to it, C_R = L_local
  // + sum W_i C_i, child by child in order as a recursion sums them. Children come after
  // their parents in the arena, so a node's are final when it is reached from the end.
  void AddChildColours(std::uint32_t first) {
    for (auto i = static_cast<std::uint32_t>(nodes_.size()); i-- > first;) {
      Ray& ray = nodes_[i];
      if (ray.childCount == 0) continue;
      Colour colour = ray.colour;
      for (std::uint32_t c = 0; c < ray.childCount; ++c) {
        const Ray& child = nodes_[ray.firstChild + c];
        colour += child.weight * child.colour;
      }
      ray.colour = colour;
    }
  }

  Ray& operator[](std::uint32_t i) { return nodes_[i]; }
  const Ray& operator[](std::uint32_t i) const { return nodes_[i]; }
  std::size_t Size() const { return nodes_.size(); }
  const std::vector<Ray>& Nodes() const { return nodes_; }

 private:
  std::vector<Ray> nodes_;
};

}  // namespace glint
