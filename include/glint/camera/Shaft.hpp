// Shaft culling (Haines and Wallace, "Shaft culling for efficient ray-cast radiosity",
// 1991): every segment from a point of one convex set to a point of another lies in
// the convex hull of the two sets, so an object that a plane separates from that hull
// meets none of the segments. A Pixel's camera rays (the eye to its patch of wall) and
// the shadow rays from that patch to the area light are such segments.
//
// Separation along a unit direction n is decided by support functions,
//   h_K(n) = max over x in K of n.x:   K lies in n.x <= h_K(n), the hull in n.x >= -h_S(-n),
// so K and the hull are apart if h_K(n) + margin < -h_S(-n). That test is exact for the
// hull of points (the largest n.p) and for spheres, boxes and rectangles. The directions
// tried are from the object's centre to the nearest point of a few guide segments laid
// inside the shaft: a poor direction only loses a cull, it never gives a wrong answer.
#pragma once

#include <array>

#include "glint/core/Math.hpp"

namespace glint {

class Shaft {
 public:
  static constexpr int kMaxPoints = 8;
  static constexpr int kMaxGuides = 9;

  // The hull's vertices: at most kMaxPoints.
  void AddPoint(vec3 p) { points_[static_cast<std::size_t>(pointCount_++)] = p; }
  // A segment inside the hull (between two of its points, say) whose nearest point to
  // an object gives a direction to try; at most kMaxGuides.
  void AddGuide(vec3 a, vec3 b) { guides_[static_cast<std::size_t>(guideCount_++)] = {a, b}; }

  // h_S(n) = max over the vertices p of n.p.
  double Support(vec3 n) const {
    double h = -kInfinity;
    for (int i = 0; i < pointCount_; ++i) {
      h = std::max(h, glm::dot(n, points_[static_cast<std::size_t>(i)]));
    }
    return h;
  }

  // Whether a plane separates the hull from a convex object, with a gap wider than
  // `margin`. The object is given by its centre and its support function h_K(n) for
  // unit n (Sphere, Cube and Rectangle have one).
  template <class Object>
  bool Misses(const Object& object, double margin) const {
    const vec3 c = object.Centre();
    for (int i = 0; i < guideCount_; ++i) {
      const Guide& g = guides_[static_cast<std::size_t>(i)];
      const vec3 toHull = ClosestOnSegment(g.a, g.b, c) - c;
      const double length = glm::length(toHull);
      if (!(length > 0.0)) continue;  // the centre lies on the guide: no direction
      const vec3 n = toHull / length;
      if (object.Support(n) + margin < -Support(-n)) return true;
    }
    return false;
  }

 private:
  struct Guide {
    vec3 a;
    vec3 b;
  };

  static vec3 ClosestOnSegment(vec3 a, vec3 b, vec3 p) {
    const vec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double s = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return a + s * ab;
  }

  std::array<vec3, kMaxPoints> points_{};
  std::array<Guide, kMaxGuides> guides_{};
  int pointCount_ = 0;
  int guideCount_ = 0;
};

}  // namespace glint
