// A pixel's camera rays traced in lock-step, one ray per SIMD lane (Pixel::TracePass,
// Integrator::TraceLanes), kMax at a time, in structure-of-arrays form so that a lane
// group loads each quantity of W rays with one instruction. The pixel fills in the
// numbers its sampler drew for each ray; the integrator's lanes fill in where the ray
// went and the colour it brought back, from which the pixel writes each ray's own node
// of its RayTree (the design's trees stay one per ray).
#pragma once

#include <array>
#include <cstdint>

namespace glint {

// The lanes have no initialisers, so that a pixel's 8 sets of a group of 64 rays
// (Pixel::TracePassInGroups) are not zeroed for each pixel (18 KB); `RayLanes lanes{}`
// zeroes them. A kernel fills the spare lanes up to its width itself.
struct RayLanes {
  static constexpr int kMax = 8;  // AVX-512 holds 8 doubles
  using Lane = std::array<double, kMax>;

  // In: each ray's point of the pixel (image coordinates) and its first light point's
  // numbers (SampleDimension::kPixel, SampleDimension::Light(0)).
  alignas(64) Lane px, py, lightU, lightV;
  // Out: the unit direction, the point the ray ended at, its colour.
  alignas(64) std::array<Lane, 3> direction, end, colour;
  // Out, for the integrator's own use: the light point, and 1 where the light point and
  // the wall face each other (a shadow ray is cast), 0 elsewhere.
  alignas(64) std::array<Lane, 3> lightPoint;
  alignas(64) Lane lit;
  std::int32_t object = -1;  // the object every ray ended at
  // Out, from CameraHitLanes (pixels whose rays may meet objects): each ray's first hit,
  // at distance t, as Scene::Intersect finds it: Scene::Closest's code, -1 where the
  // lanes leave the ray to Scene::Intersect (a rare case: a direction component 0, ...);
  // the sphere's or cube's index; the box face (IntersectSlabs' order) of the wall or cube.
  alignas(64) Lane t, closest, closestIndex, closestFace;
  // Out, from the same lanes: where a sphere was met first, its unit outward normal at
  // the hit (Sphere::FillHit's normalize(o + t d - centre)); elsewhere meaningless.
  alignas(64) std::array<Lane, 3> sphereNormal;
  // In, for HitLanes (rays from any origin): each ray's origin; its unit direction is in
  // `direction`.
  alignas(64) std::array<Lane, 3> start;
};

}  // namespace glint
