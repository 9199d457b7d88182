#include "glint/transport/SphereReflection.hpp"

namespace glint {

namespace {

// A direction in the plane of the path, (cos(phi), sin(phi)) in the basis (a, e): angles
// stay in [0, pi], so that they compare by the sign of a cross product, and no step of
// the solver needs a trigonometric function.
struct Unit2 {
  double c, s;

  static Unit2 Normalised(double c, double s) {
    const double inv = 1.0 / std::sqrt(c * c + s * s);
    return {c * inv, s * inv};
  }
  // Whether this direction's angle is below o's (for angles less than pi apart).
  bool Below(Unit2 o) const { return c * o.s - s * o.c > 0.0; }
  // Rotated by -alpha, for cos(alpha) = ca, sin(alpha) = sa.
  Unit2 RotatedBack(double ca, double sa) const { return {c * ca + s * sa, s * ca - c * sa}; }
};

// The geometry of the path through m(phi): from x at distance p on the axis, from y at
// distance q at the angle beta (cos, sin given), on a sphere of radius r.
struct PathAt {
  double sinPsi, cosPsi;  // psi = beta - phi: m's angle from y's side
  double dx2, dy2;        // |x - m|^2, |y - m|^2, from 2D coordinates: x = (p, 0), m = r n
  double invDx, invDy;
  double h;  // sin(incidence from x) - sin(incidence from y)

  PathAt(Unit2 m, double p, double q, double r, Unit2 beta)
      : sinPsi(beta.s * m.c - beta.c * m.s),
        cosPsi(beta.c * m.c + beta.s * m.s),
        dx2((p - r * m.c) * (p - r * m.c) + (r * m.s) * (r * m.s)),
        dy2((q - r * cosPsi) * (q - r * cosPsi) + (r * sinPsi) * (r * sinPsi)),
        invDx(1.0 / std::sqrt(dx2)),
        invDy(1.0 / std::sqrt(dy2)),
        h(p * m.s * invDx - q * sinPsi * invDy) {}
  // dh / dphi, positive on the bracket: d/dphi (p sin(phi) / dx) = p (cos(phi) - p r
  // sin^2(phi) / dx^2) / dx, and the same from y's side.
  double Slope(Unit2 m, double p, double q, double r) const {
    return p * (m.c - p * r * m.s * m.s * invDx * invDx) * invDx +
           q * (cosPsi - q * r * sinPsi * sinPsi * invDy * invDy) * invDy;
  }
};

}  // namespace

std::optional<SphereReflection> ReflectOffSphere(vec3 centre, double radius, vec3 x, vec3 y) {
  const double r = radius;
  const vec3 fx = x - centre;
  const vec3 fy = y - centre;
  const double p = glm::length(fx);
  const double q = glm::length(fy);
  if (!(p > r && q > r)) return std::nullopt;
  // The plane of the path: m(phi) = c + R (cos(phi) a + sin(phi) e), with a toward x and
  // y at the angle beta in [0, pi] from a.
  const vec3 a = fx / p;
  const double cosBeta = std::clamp(glm::dot(a, fy / q), -1.0, 1.0);
  const vec3 w = fy / q - cosBeta * a;
  const double sinBeta = glm::length(w);
  if (!(sinBeta > 0.0)) return std::nullopt;  // x, c and y in a line: a set of measure 0
  const Unit2 beta{cosBeta, sinBeta};
  // x sees the points within acos(R / p) of a, y those within acos(R / q) of y's
  // direction: the bracket [lo, hi] where both see m.
  const double rp = r / p;
  const double rq = r / q;
  const Unit2 hi = cosBeta > rp ? beta : Unit2{rp, std::sqrt((1.0 - rp) * (1.0 + rp))};
  Unit2 lo = cosBeta < rq ? beta.RotatedBack(rq, std::sqrt((1.0 - rq) * (1.0 + rq))) : Unit2{1, 0};
  if (!lo.Below(hi)) return std::nullopt;  // no point of the sphere that both see
  Unit2 upper = hi;

  // h(phi) = 0 by Newton's method, each step a rotation by atan(dphi) (quadratic
  // convergence all the same), falling back to bisection where a step leaves the
  // bracket. First guess: for x and y far away the normal halves beta; seen from m they
  // are turned by about (R / p) sin(phi) and (R / q) sin(beta - phi), which moves it by
  // (R / 2) sin(beta / 2) (1 / q - 1 / p).
  const Unit2 half = Unit2::Normalised(1.0 + beta.c, beta.s);
  const double turn = 0.5 * r * half.s * (1.0 / q - 1.0 / p);
  Unit2 m = Unit2::Normalised(half.c - half.s * turn, half.s + half.c * turn);
  if (!(lo.Below(m) && m.Below(upper))) m = Unit2::Normalised(lo.c + upper.c, lo.s + upper.s);
  for (int i = 0; i < 64; ++i) {
    const PathAt path(m, p, q, r, beta);
    if (path.h == 0.0) break;
    (path.h < 0.0 ? lo : upper) = m;
    const double step = -path.h / path.Slope(m, p, q, r);
    const Unit2 next = Unit2::Normalised(m.c - m.s * step, m.s + m.c * step);
    const bool converged = std::abs(step) < 1e-6;  // what is left is of the order of step^2
    if (converged || (lo.Below(next) && next.Below(upper))) {
      m = next;
      if (converged) break;
    } else {  // Newton left the bracket: bisect
      m = Unit2::Normalised(lo.c + upper.c, lo.s + upper.s);
      if (lo.c * upper.s - lo.s * upper.c < 1e-12) break;  // a bracket of 1e-12 radians
    }
  }

  const PathAt path(m, p, q, r, beta);
  SphereReflection s{};
  s.normal = m.c * a + m.s * (w / sinBeta);
  s.point = centre + r * s.normal;
  s.toX = path.dx2 * path.invDx;
  s.toY = path.dy2 * path.invDy;
  // n.(x - m) = p cos(phi) - R; the same from y's side at the root.
  s.cosTheta = (p * m.c - r) / s.toX;
  if (!(s.cosTheta > 0.0 && q * path.cosPsi - r > 0.0)) return std::nullopt;  // grazing
  const double d1 = s.toX;
  const double d2 = s.toY;
  s.spread =
      (d1 + d2 + 2.0 * d1 * d2 / (r * s.cosTheta)) * (d1 + d2 + 2.0 * d1 * d2 * s.cosTheta / r);
  return s;
}

}  // namespace glint
