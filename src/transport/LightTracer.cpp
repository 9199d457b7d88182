#include "glint/transport/LightTracer.hpp"

#include "glint/camera/Camera.hpp"
#include "glint/sampling/Sampling.hpp"
#include "glint/transport/Fresnel.hpp"
#include "glint/transport/Phong.hpp"

namespace glint {

LightTracer::LightTracer(const Scene& scene, const Light& light, const MonteCarloOptions& options,
                         const Pinhole& camera, bool joinSingleMirror, Joins joins)
    : scene_(scene),
      light_(light),
      options_(options),
      camera_(camera),
      joinSingleMirror_(joinSingleMirror),
      joins_(joins),
      scale_(static_cast<double>(kPathsPerRay) * static_cast<double>(camera.Pixels())) {}

void LightTracer::Trace(Camera& camera, Sampler& sampler, int count, RenderStats& stats) const {
  const vec3 normal = light_.Normal();
  const Frame frame = Frame::FromZ(normal);
  // beta = Le cos / (p_A p_w) = Le cos / ((1 / A) (cos / pi)) = Le A pi.
  const Colour beta0 = light_.Radiance() * (light_.Area() * kPi);
  for (int i = 0; i < count; ++i) {
    sampler.StartSample(i);
    const Sample2 a = sampler.Get2D(SampleDimension::Light(0));
    const Sample2 b = sampler.Get2D(SampleDimension::Scatter(0));
    PathState path;
    const vec3 w = SampleCosineDirection(frame, b.u, b.v);
    path.origin = OffsetRayOrigin(light_.SamplePoint(a.u, a.v), normal, w);
    path.direction = w;
    path.beta = beta0;
    std::uint32_t node = 0;
    Follow(camera, sampler, path, node, beta0, stats);
  }
}

bool LightTracer::Survives(Colour& beta, Colour beta0, Sampler& sampler,
                           std::uint32_t dimension) const {
  const double relative = MaxComponent(beta) / MaxComponent(beta0);
  if (!(relative > 0.0)) return false;
  const double q = relative / options_.rouletteThreshold;
  if (q >= 1.0) return true;
  if (sampler.Get1D(dimension) >= q) return false;
  beta /= q;
  return true;
}

void LightTracer::Follow(Camera& camera, Sampler& sampler, PathState path, std::uint32_t& node,
                         Colour beta0, RenderStats& stats) const {
  // A camera path reaches the light by a ray of depth maxDepth - 1 at most: through
  // maxDepth - 2 objects after its wall. Longer paths are neither side's.
  const int maxInterior = options_.maxDepth - 2;
  while (true) {
    ++stats.lightRays;
    Hit hit;
    if (!scene_.Intersect(path.origin, path.direction, hit, /*withAreaLight=*/true)) return;
    if (hit.light) return;  // the light reflects nothing
    ++node;
    const Material& m = *hit.material;
    const vec3 d = path.direction;
    const vec3 n = FacingNormal(d, hit.normal);
    if (m.type == MaterialType::Lambertian) {
      // Light straight from the light is next-event estimation's; one mirror's image of
      // it on the first wall MirroredLight's (then the whole path is, as the camera's
      // ray that leaves a wall and meets it is counted 0).
      if (joins_ == Joins::Direct) {
        if (path.interior == 0) Join(camera, hit, n, path, stats);
        return;
      }
      if (path.vertices == 0) return;
      if (path.interior == 1 && path.mirrors == 1 && !joinSingleMirror_) return;
      Join(camera, hit, n, path, stats);
    }
    if (path.interior + 1 > maxInterior) return;
    PathState next = path;
    ++next.interior;
    if (m.type != MaterialType::Lambertian) ++next.vertices;
    switch (m.type) {
      case MaterialType::Mirror:
        ++next.mirrors;
        next.direction = glm::normalize(Reflect(d, n));
        next.beta = path.beta * m.reflectance;
        break;
      case MaterialType::Phong: {
        const Sample2 uv = sampler.Get2D(SampleDimension::Scatter(node));
        const PhongSample s = SamplePhong(m, d, n, uv.u, uv.v);
        const double cosEye = glm::dot(n, s.direction);
        const double cosLight = -glm::dot(n, d);
        if (!(cosEye > 0.0) || !(cosLight > 0.0)) return;
        // p_s0 / p_t1 at this vertex: the camera's density toward the light over the
        // light path's toward the eye, in projected solid angle (the lobe is symmetric).
        const double factor = 1.0 / PhongFactor(cosLight, cosEye, options_.branches);
        if (path.vertices == 0) {
          next.firstIsPhong = true;
          if (options_.strategy != MonteCarloOptions::Strategy::Brdf) {
            // p_s1 / p_t1: the light point's density against this path's first two
            // vertices', G (s.pdf / cos_eye), G = cos_light cos_y / r^2.
            const vec3 e = hit.point - path.origin;
            const double cosY = glm::dot(light_.Normal(), d);
            const double g = cosLight * cosY / glm::dot(e, e);
            next.s1 = cosEye / (g * s.pdf);
          }
        } else {
          next.s1 *= factor;
        }
        next.s0 *= factor;
        next.direction = s.direction;
        next.beta = path.beta * s.weight;
        break;
      }
      case MaterialType::Glass: {
        const vec3 mirror = glm::normalize(Reflect(d, hit.normal));
        const DielectricInterface glass = CrossDielectric(d, hit.normal, m.ior);
        const double f = GlassReflectance(glass, m.ior, options_.fresnel);
        if (options_.glass == MonteCarloOptions::Glass::Choose) {
          if (!glass.refracted || sampler.Get1D(SampleDimension::Choice(node)) < f) {
            next.direction = mirror;
          } else {
            next.direction = *glass.refracted;
            next.inside = !path.inside;
          }
          break;
        }
        // Split: the reflection first (its own branch), then on with the refraction.
        const std::uint32_t here = node;
        if (f > 0.0) {
          PathState reflected = next;
          reflected.direction = mirror;
          reflected.beta = path.beta * f;
          if (Survives(reflected.beta, beta0, sampler, SampleDimension::Roulette(here))) {
            reflected.origin = OffsetRayOrigin(hit.point, hit.normal, mirror);
            Follow(camera, sampler, reflected, node, beta0, stats);
          }
        }
        if (!glass.refracted || !(f < 1.0)) return;
        next.direction = *glass.refracted;
        next.inside = !path.inside;
        next.beta = path.beta * (1.0 - f);
        if (!Survives(next.beta, beta0, sampler, SampleDimension::Extra(here, 1) + 2)) return;
        next.origin = OffsetRayOrigin(hit.point, hit.normal, next.direction);
        path = next;
        continue;
      }
      case MaterialType::Lambertian: {
        // On, cosine-distributed, to be seen from the next surface (a caustic lighting
        // the ceiling by way of the floor): f cos / p = rho, and the camera's ray at the
        // same point has the same density, so r gains no factor here.
        const Sample2 uv = sampler.Get2D(SampleDimension::Scatter(node));
        next.direction = SampleCosineDirection(n, uv.u, uv.v);
        next.beta = path.beta * m.reflectance;
        break;
      }
    }
    if (!Survives(next.beta, beta0, sampler, SampleDimension::Roulette(node))) return;
    next.origin = OffsetRayOrigin(hit.point, hit.normal, next.direction);
    path = next;
  }
}

void LightTracer::Join(Camera& camera, const Hit& hit, vec3 n, const PathState& path,
                       RenderStats& stats) const {
  const PinholeImportance importance = camera_.Importance(hit.point, n);
  if (!(importance.we > 0.0)) return;
  const vec3 toEye = camera_.Eye() - hit.point;
  if (!(glm::dot(n, toEye) > 0.0)) return;  // the eye sees the other side
  ++stats.shadowRays;
  if (scene_.Occluded(OffsetRayOrigin(hit.point, n, toEye), camera_.Eye())) return;
  // The other strategies' densities over this one's (LightTracer.hpp), with the factor
  // W_e(x) / (lambda P) they share here.
  const double shared = importance.we / scale_;
  const bool cameraHits =
      !(path.firstIsPhong && options_.strategy == MonteCarloOptions::Strategy::Light);
  const double s0 = cameraHits ? shared * light_.Area() * path.s0 : 0.0;
  const double s1 = shared * path.s1;
  const double weight = joins_ == Joins::Direct ? 1.0 : 1.0 / (1.0 + s0 * s0 + s1 * s1);
  const Colour splat = path.beta * hit.material->reflectance * (kInvPi * shared * weight);
  camera.Splat(importance.pixel, splat, stats);
}

}  // namespace glint
