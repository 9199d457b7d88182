#include "glint/transport/MirroredLight.hpp"

#include "glint/scene/Scene.hpp"
#include "glint/transport/SphereReflection.hpp"

namespace glint {

namespace {
// Whether some corner of the light lies strictly in front of the face's plane: a face
// with the whole light behind it can never show it.
bool LightInFront(const Light& light, const Rectangle& face) {
  const Rectangle& l = light.Shape();
  for (const vec3 corner :
       {l.PointFromUV(0, 0), l.PointFromUV(1, 0), l.PointFromUV(0, 1), l.PointFromUV(1, 1)}) {
    if (glm::dot(corner - face.Corner(), face.Normal()) > 0.0) return true;
  }
  return false;
}
}  // namespace

MirroredLight::MirroredLight(const Scene& scene, const Light& light)
    : scene_(scene), light_(light) {
  for (const Cube& c : scene.cubes) {
    if (c.GetMaterial().type != MaterialType::Mirror) continue;
    for (const Rectangle& face : c.Faces()) {
      if (!LightInFront(light, face)) continue;
      planes_.push_back(
          {face, c.GetMaterial().reflectance, Reflect(light.Normal(), face.Normal())});
    }
  }
  for (const Sphere& s : scene.spheres) {
    if (s.GetMaterial().type != MaterialType::Mirror) continue;
    spheres_.push_back({s.Centre(), s.Radius(), s.GetMaterial().reflectance});
  }
}

bool MirroredLight::Blocked(vec3 x, vec3 n, vec3 m, vec3 mn, vec3 y, RenderStats& stats) const {
  // m moved off the mirror to the outside, where x and y are: neither segment can then
  // touch the mirror itself (both stay above its tangent plane).
  const vec3 mOff = OffsetRayOrigin(m, mn, mn);
  ++stats.shadowRays;
  if (scene_.Occluded(OffsetRayOrigin(x, n, m - x), mOff)) return true;
  ++stats.shadowRays;
  return scene_.Occluded(mOff, y);
}

Colour MirroredLight::Irradiance(vec3 x, vec3 n, double u, double v, RenderStats& stats) const {
  const vec3 y = light_.SamplePoint(u, v);
  Colour sum(0.0);
  for (const PlaneMirror& p : planes_) {
    // Heights of x and y above the face's plane; both must be in front of it.
    const vec3 normal = p.face.Normal();
    const double hy = glm::dot(y - p.face.Corner(), normal);
    if (hy <= 0.0 || glm::dot(x - p.face.Corner(), normal) <= 0.0) continue;
    const vec3 image = y - 2.0 * hy * normal;  // y's mirror image behind the face
    const vec3 toImage = image - x;
    const double cosX = glm::dot(n, toImage);  // times |x - image|, as cosY
    const double cosY = -glm::dot(p.imageNormal, toImage);
    double t = 0.0;
    if (cosX <= 0.0 || cosY <= 0.0 || !p.face.Intersect(x, toImage, 1.0, t)) continue;
    if (Blocked(x, n, x + t * toImage, normal, y, stats)) continue;
    // A plane mirror keeps the path's length: spread = |x - image|^2.
    const double r2 = glm::dot(toImage, toImage);
    sum += p.rho * (cosX * cosY / (r2 * r2));
  }
  for (const SphereMirror& s : spheres_) {
    const std::optional<SphereReflection> r = ReflectOffSphere(s.centre, s.radius, x, y);
    if (!r) continue;
    const double cosX = glm::dot(n, r->point - x) / r->toX;
    const double cosY = glm::dot(light_.Normal(), r->point - y) / r->toY;
    if (cosX <= 0.0 || cosY <= 0.0) continue;
    if (Blocked(x, n, r->point, r->normal, y, stats)) continue;
    sum += s.rho * (cosX * cosY / r->spread);
  }
  return light_.Radiance() * sum * light_.Area();
}

}  // namespace glint
