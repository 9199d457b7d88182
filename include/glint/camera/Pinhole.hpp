// The camera's geometry without its pixels: the eye, the view plane in front of it and
// the plane's grid of W x H pixels. It turns image coordinates into rays (a camera ray
// of pixel (x, y) goes through a uniform point of the pixel's patch of the plane: the
// box filter) and, for light tracing, a point of the scene back into the pixel it is
// seen in and the camera's importance there.
#pragma once

#include <cstddef>

#include "glint/core/Math.hpp"

namespace glint {

// Where a scene point shows in the image, and the density with which the camera rays
// of that pixel reach it.
struct PinholeImportance {
  // W_e of the pixel at the point, per unit area of the surface (see Pinhole::Importance);
  // 0 if the point is not in front of the eye or projects outside the image.
  double we = 0.0;
  std::size_t pixel = 0;  // row by row
};

class Pinhole {
 public:
  Pinhole() = default;
  // `halfWidth`, `halfHeight`: half the view plane's extent; `distance`: from the eye to
  // the plane along `viewDirection`, which is -z (the room's axis).
  Pinhole(vec3 eye, vec3 viewDirection, double distance, double halfWidth, double halfHeight,
          int width, int height);

  vec3 Eye() const { return eye_; }
  vec3 ViewDirection() const { return viewDirection_; }
  double Distance() const { return distance_; }
  double HalfWidth() const { return halfWidth_; }
  double HalfHeight() const { return halfHeight_; }
  vec3 ViewPlaneCentre() const { return planeCentre_; }
  double PixelWidth() const { return pixelWidth_; }  // of the view plane, in metres
  double PixelHeight() const { return pixelHeight_; }
  int Width() const { return width_; }
  int Height() const { return height_; }
  std::size_t Pixels() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  }

  // The point of the view plane at image coordinates (px, py) in [0, W] x [0, H],
  // (0, 0) being the top-left corner of pixel (0, 0).
  vec3 ViewPlanePoint(double px, double py) const {
    // Image x grows to the right (+x in the world), image y grows downward (-y).
    // pixelWidth_ = 2 halfWidth / W, set once: no division per ray.
    const double sx = px * pixelWidth_ - halfWidth_;
    const double sy = halfHeight_ - py * pixelHeight_;
    return planeCentre_ + vec3(sx, sy, 0.0);
  }
  // Unit direction from the eye through image coordinates (px, py).
  vec3 DirectionThrough(double px, double py) const {
    return glm::normalize(ViewPlanePoint(px, py) - eye_);
  }

  // The camera's importance at surface point x (unit normal n on either side), per unit
  // area of the surface, for the pixel x projects into. A pixel's value is the mean over
  // its camera rays, uniform over its patch of area a = pixelWidth x pixelHeight of the
  // plane at distance D, of the radiance they bring back:
  //   I_j = (1/a) Int_patch L dA_plane = Int W_e(x) L(x -> eye) dA(x),
  //   W_e(x) = D^2 / (a cos^3(theta)) * cos(theta_x) / |x - eye|^2,
  // from dA_plane = (D / cos(theta))^2 dw / cos(theta) and dw = cos(theta_x) dA / r^2
  // (theta from the view direction, theta_x from x's normal). It is pbrt-v3's pinhole
  // W_e = 1 / (A cos^4 theta) (section 16.1.1, eq. 16.3, A the image's area at distance 1)
  // for one pixel, times the cos(theta) cos(theta_x) / r^2 that turns projected solid
  // angle at the eye into area at x. It is also the density, per unit area at x, of a
  // camera ray of that pixel hitting x: the two strategies' MIS weights use it so.
  // Visibility is the caller's to test.
  PinholeImportance Importance(vec3 x, vec3 n) const;

 private:
  vec3 eye_{0.0};
  vec3 viewDirection_{0.0, 0.0, -1.0};
  vec3 planeCentre_{0.0};
  double distance_ = 1.0;
  double halfWidth_ = 1.0;
  double halfHeight_ = 1.0;
  double pixelWidth_ = 1.0;  // the view plane's extent of one pixel, in metres
  double pixelHeight_ = 1.0;
  double inversePixelArea_ = 1.0;
  int width_ = 1;
  int height_ = 1;
};

}  // namespace glint
