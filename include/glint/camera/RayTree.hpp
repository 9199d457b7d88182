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

  Ray& operator[](std::uint32_t i) { return nodes_[i]; }
  const Ray& operator[](std::uint32_t i) const { return nodes_[i]; }
  std::size_t Size() const { return nodes_.size(); }
  const std::vector<Ray>& Nodes() const { return nodes_; }

 private:
  std::vector<Ray> nodes_;
};

}  // namespace glint
