// Wall and Cube meet rays by the slab test of their box, not by testing their
// Rectangles one by one. These tests hold the fast form to the rectangles it stands
// for, on random rays and on the hard ones: origins on faces, edges and corners,
// directions in a face's plane or along an axis, from inside and from outside.
#include <gtest/gtest.h>

#include <vector>

#include "glint/sampling/Rng.hpp"
#include "glint/scene/Cube.hpp"
#include "glint/scene/Sphere.hpp"
#include "glint/scene/Wall.hpp"

namespace glint {
namespace {

struct BruteForce {
  bool hit = false;
  double t = kInfinity;
  std::vector<int> faces;  // every face within round-off of the nearest (an edge: two)
};

BruteForce Nearest(const std::vector<Rectangle>& faces, vec3 o, vec3 d) {
  BruteForce b;
  std::vector<double> ts(faces.size(), kInfinity);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    double t = 0.0;
    if (faces[i].Intersect(o, d, kInfinity, t)) ts[i] = t;
  }
  for (const double t : ts) b.t = std::min(b.t, t);
  b.hit = b.t < kInfinity;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (b.hit && ts[i] <= b.t * (1.0 + 1e-12) + 1e-15) b.faces.push_back(static_cast<int>(i));
  }
  return b;
}

// A coordinate of a test origin: inside, on the low or high face, or outside.
double Coordinate(Pcg32& rng, double lo, double hi) {
  const double u = rng.Uniform();
  if (u < 0.2) return lo;
  if (u < 0.4) return hi;
  return lo + (hi - lo) * (3.0 * rng.Uniform() - 1.0);  // [lo - s, hi + s)
}

// A unit direction, some of whose components may be exactly zero.
vec3 Direction(Pcg32& rng) {
  for (;;) {
    vec3 d;
    for (int a = 0; a < 3; ++a) d[a] = rng.Uniform() < 0.25 ? 0.0 : 2.0 * rng.Uniform() - 1.0;
    if (glm::dot(d, d) > 1e-6) return glm::normalize(d);
  }
}

template <typename Query>
void CompareOnRandomRays(vec3 lo, vec3 hi, const std::vector<Rectangle>& faces, Query query) {
  Pcg32 rng(2026, 11);
  int hits = 0;
  for (int i = 0; i < 200000; ++i) {
    const vec3 o(Coordinate(rng, lo.x, hi.x), Coordinate(rng, lo.y, hi.y),
                 Coordinate(rng, lo.z, hi.z));
    const vec3 d = Direction(rng);
    const BruteForce expected = Nearest(faces, o, d);
    Hit hit;
    int face = -1;
    const bool got = query(o, d, hit, face);
    ASSERT_EQ(got, expected.hit) << "o " << o.x << " " << o.y << " " << o.z << " d " << d.x << " "
                                 << d.y << " " << d.z;
    if (!got) continue;
    ++hits;
    EXPECT_NEAR(hit.t, expected.t, 1e-12 * (1.0 + expected.t));
    EXPECT_NE(std::find(expected.faces.begin(), expected.faces.end(), face), expected.faces.end())
        << "face " << face;
    EXPECT_EQ(hit.normal, faces[static_cast<std::size_t>(face)].Normal());
  }
  EXPECT_GT(hits, 25000);  // the rays do meet the box
}

TEST(Slabs, WallMatchesItsFiveRectangles) {
  const Wall wall(vec3(-0.5, 0.25, 1.0), 2.0, {});
  std::vector<Rectangle> faces;
  for (int s = 0; s < Wall::kSides; ++s) faces.push_back(wall.Face(s));
  CompareOnRandomRays(wall.Position(), wall.Position() + vec3(wall.Size()), faces,
                      [&](vec3 o, vec3 d, Hit& hit, int& face) {
                        const bool h = wall.Intersect(o, d, kInfinity, hit);
                        face = hit.object;  // firstObject 0: the side
                        return h;
                      });
}

TEST(Slabs, CubeMatchesItsSixRectangles) {
  const Cube cube(vec3(0.42, 0.0, 0.06), 0.28, Material{}, 0);
  const std::vector<Rectangle> faces(cube.Faces().begin(), cube.Faces().end());
  CompareOnRandomRays(cube.Position(), cube.Position() + vec3(cube.Size()), faces,
                      [&](vec3 o, vec3 d, Hit& hit, int& face) {
                        const bool h = cube.Intersect(o, d, kInfinity, hit);
                        for (std::size_t i = 0; i < faces.size(); ++i) {
                          if (h && hit.normal == faces[i].Normal()) face = static_cast<int>(i);
                        }
                        return h;
                      });
}

// The shadow-ray tests take a segment's end instead of a unit direction: they must
// agree with the closest hit below the segment's length, on 100 000 random segments
// starting around the box [lo, hi] with lengths up to maxLength (except within
// round-off of an end). Counts the segments that meet the shape in `blocked`.
template <typename Shape>
void CompareSegmentsWithRays(const Shape& shape, vec3 lo, vec3 hi, double maxLength, Pcg32 rng,
                             int& blocked) {
  blocked = 0;
  for (int i = 0; i < 100000; ++i) {
    const vec3 o(Coordinate(rng, lo.x, hi.x), Coordinate(rng, lo.y, hi.y),
                 Coordinate(rng, lo.z, hi.z));
    const vec3 d = Direction(rng);
    const double length = maxLength * rng.Uniform();
    Hit hit;
    const bool closeToAnEnd =
        shape.Intersect(o, d, kInfinity, hit) && std::abs(hit.t - length) < 1e-12;
    if (closeToAnEnd) continue;
    const bool segment = shape.IntersectsSegment(o, length * d);
    ASSERT_EQ(segment, shape.Intersect(o, d, length, hit));
    blocked += segment ? 1 : 0;
  }
}

TEST(Slabs, CubeSegmentTestAgreesWithTheRayTest) {
  const Cube cube(vec3(0.42, 0.0, 0.06), 0.28, Material{}, 0);
  int blocked = 0;
  CompareSegmentsWithRays(cube, vec3(0.42, 0.0, 0.06), vec3(0.70, 0.28, 0.34), 0.6, Pcg32(5, 5),
                          blocked);
  EXPECT_GT(blocked, 5000);  // the segments do meet the cube
}

TEST(Slabs, SphereSegmentTestAgreesWithTheRayTest) {
  const Sphere sphere(vec3(0.22, 0.18, 0.40), 0.18, Material{}, 0);
  int blocked = 0;
  CompareSegmentsWithRays(sphere, vec3(0.04, 0.0, 0.22), vec3(0.40, 0.36, 0.58), 0.8, Pcg32(6, 6),
                          blocked);
  EXPECT_GT(blocked, 3000);  // the segments do meet the sphere
}

// The cube's bounding-sphere early-out must not cut off a ray that just touches a
// corner from far away.
TEST(Slabs, RayGrazingACubeCornerFromAfarStillHits) {
  const Cube cube(vec3(0.0), 1.0, Material{}, 0);
  const vec3 corner(1.0, 1.0, 1.0);
  for (const double distance : {1.0, 10.0, 1000.0}) {
    const vec3 d = glm::normalize(vec3(-1.0, -1.0, -1.0));
    const vec3 o = corner - distance * d;
    Hit hit;
    ASSERT_TRUE(cube.Intersect(o, d, kInfinity, hit)) << distance;
    EXPECT_NEAR(glm::length(hit.point - corner), 0.0, 1e-9 * distance);
    // Tangent to the corner, past the face diagonals: touches the closed box at one point.
    const vec3 side = glm::normalize(vec3(1.0, -1.0, 0.0));
    Hit edge;
    EXPECT_TRUE(cube.Intersect(corner - distance * side, side, kInfinity, edge) ||
                distance > 1.0)  // along the edge line from afar round-off may go either way
        << distance;
  }
}

// From inside the room a ray always meets a wall or leaves through the open front,
// also when it starts on an edge and runs in a wall's plane or along the edge.
TEST(Slabs, NoRayFromInsideTheRoomSlipsBetweenWalls) {
  const Wall wall;
  const vec3 starts[] = {vec3(0.0, 0.0, 0.5), vec3(1.0, 0.0, 0.5), vec3(0.0, 1.0, 0.5),
                         vec3(0.3, 0.0, 0.5), vec3(0.5)};
  const vec3 directions[] = {vec3(0, 0, -1),
                             vec3(0, 1, 0),
                             vec3(1, 0, 0),
                             glm::normalize(vec3(1, 1, 0)),
                             glm::normalize(vec3(0, 1, -1)),
                             vec3(0, 0, 1)};
  for (const vec3 o : starts) {
    for (const vec3 d : directions) {
      Hit hit;
      const bool hits = wall.Intersect(o, d, kInfinity, hit);
      // Out of the room at t = 0 (starting on a wall, heading out of it), or out the front.
      const bool leaves = d.z > 0.0 || (o.x == 0.0 && d.x < 0.0) || (o.x == 1.0 && d.x > 0.0) ||
                          (o.y == 0.0 && d.y < 0.0) || (o.y == 1.0 && d.y > 0.0);
      EXPECT_EQ(hits, !leaves) << o.x << " " << o.y << " " << o.z << " -> " << d.x << " " << d.y
                               << " " << d.z;
      if (hits) {
        EXPECT_GT(hit.t, 0.0);
        EXPECT_TRUE(wall.Contains(hit.point));
      }
    }
  }
}

}  // namespace
}  // namespace glint
