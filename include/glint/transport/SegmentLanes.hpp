// The objects a shadow segment may meet, as the segment lanes (SegmentLanes-inl.h) read
// them: each sphere's centre and r^2, each cube's centre, corners and bound, as the scalar
// code holds them (Sphere::IntersectsSegment, Cube::IntersectsSegment).
#pragma once

#include <array>
#include <vector>

#include "glint/scene/Scene.hpp"

namespace glint {

struct SegmentLaneScene {
  struct SphereTerms {
    std::array<double, 3> centre;
    double r2;  // radius * radius
  };
  struct CubeTerms {
    std::array<double, 3> centre, low, high;
    double boundRadius2;
  };
  std::vector<SphereTerms> spheres;
  std::vector<CubeTerms> cubes;

  // The scene's spheres and cubes that block a segment: all of them if `glassBlocks`
  // (Scene::Occluded, Monte Carlo's shadow rays), else the opaque ones (Whitted's).
  static SegmentLaneScene Of(const Scene& scene, bool glassBlocks);
};

}  // namespace glint
