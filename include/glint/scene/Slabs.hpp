// The slab test of an axis-aligned box [lo, hi] (Kay and Kajiya 1986): along the ray
// o + t d, slab a is crossed between (lo_a - o_a) / d_a and (hi_a - o_a) / d_a; the box
// between the largest entry (tNear) and the smallest exit (tFar). Wall and Cube are such
// boxes, so their Rectangles need no general test: three divisions find the faces.
#pragma once

#include "glint/core/Math.hpp"

namespace glint {

struct SlabCrossing {
  double tNear = -kInfinity;  // where the ray enters the box (negative: behind the origin)
  double tFar = kInfinity;    // where it leaves
  int nearFace = -1;          // face crossed at tNear: 2 axis + (0: min side, 1: max side)
  int farFace = -1;           // face crossed at tFar
  bool hit = false;           // tNear <= tFar: the line meets the closed box
};

[[gnu::always_inline]] inline SlabCrossing IntersectSlabs(vec3 o, vec3 d, vec3 lo, vec3 hi) {
  SlabCrossing c;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {  // parallel to the slab: inside it for all t, or never
      if (o[a] < lo[a] || o[a] > hi[a]) return c;
      continue;
    }
    // Division, not a multiplication by 1/d: t is then exactly rounded, as the
    // Rectangle test computes it, and a face plane is met at the same t.
    double t0 = (lo[a] - o[a]) / d[a];
    double t1 = (hi[a] - o[a]) / d[a];
    int f0 = 2 * a;
    int f1 = 2 * a + 1;
    if (d[a] < 0.0) {
      std::swap(t0, t1);
      std::swap(f0, f1);
    }
    if (t0 > c.tNear) {
      c.tNear = t0;
      c.nearFace = f0;
    }
    if (t1 < c.tFar) {
      c.tFar = t1;
      c.farFace = f1;
    }
  }
  c.hit = c.tNear <= c.tFar;
  return c;
}

// The point at distance t on face `face` of the box, placed exactly in the face's plane.
// Built component by component: writing p[axis] through an index stores one double
// that the next 16-byte load of p cannot forward from (a stall, 8% of a profile).
inline vec3 PointOnSlabFace(vec3 o, vec3 d, double t, int face, vec3 lo, vec3 hi) {
  const vec3 p = o + t * d;
  const int axis = face / 2;
  const double plane = (face % 2 == 0) ? lo[axis] : hi[axis];
  return {axis == 0 ? plane : p.x, axis == 1 ? plane : p.y, axis == 2 ? plane : p.z};
}

}  // namespace glint
