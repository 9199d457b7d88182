// A Ray is a node of the design's ray tree: it starts at `start`, travels along the
// unit `direction`, carries the `importance` of the path that led to it and, once
// traced, the `colour` (radiance) it brings back. Its colour is
//   C_R = L_local + sum_i W_i C_i            (the design's C_R = sum W_i C_i)
// over its children i, each of which stores its own weight W_i relative to this ray.
#pragma once

#include <cstdint>

#include "glint/core/Math.hpp"

namespace glint {

enum class RayKind : std::uint8_t { Camera, Reflected, Refracted, Diffuse };

struct Ray {
  static constexpr std::uint32_t kNoChild = 0xffffffffU;

  Ray();

  vec3 start{0.0};
  vec3 direction{0.0, 0.0, -1.0};  // unit length
  vec3 end{0.0};                   // where it hit something (start if it escaped)
  Colour weight{1.0};              // W_i relative to the parent
  Colour importance{1.0};          // product of the weights from the camera down
  Colour colour{0.0};              // radiance brought back, C_R
  // Monte Carlo: solid-angle density the direction was sampled with, times the number
  // of sibling samples (for multiple importance sampling); 0 for a direction that was
  // not sampled from a density (camera, mirror, glass).
  double pdf = 0.0;
  std::uint32_t firstChild = kNoChild;  // children are contiguous in the RayTree
  std::uint32_t childCount = 0;
  std::int32_t object = -1;  // scene object it hit (-1: nothing, it left the room)
  std::uint8_t depth = 0;    // 0 for camera rays
  RayKind kind = RayKind::Camera;
  bool final = false;   // spawned no children: its colour is local light only
  bool inside = false;  // travels inside a transparent object
  // Monte Carlo: the light this ray may reach was counted by next-event estimation
  // already, so its emission counts 0: a diffuse ray's (at the wall it left), and the
  // mirror reflection of a diffuse ray (MirroredLight, at that wall).
  bool lightCounted = false;
  // Monte Carlo with light tracing (LightTracer.hpp): for a ray on its way from a wall the
  // camera sees, through mirrors, glass and Phong objects, the ratio r = p_t1 / p_s0 of
  // light tracing's density to this path's were it to reach the light; 0 for any other.
  double causticRatio = 0.0;

  vec3 At(double t) const { return start + t * direction; }
};

// Defaulted here rather than in the class, so the constructor is user-provided and a
// new tree node is built from its members' initialisers alone, not zero-filled first
// (the fill was a rep stos of 184 bytes per node).
inline Ray::Ray() = default;

}  // namespace glint
