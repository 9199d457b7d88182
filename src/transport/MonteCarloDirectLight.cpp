// The Monte Carlo integrator's light: next-event estimation to the area light and the
// multiple-importance weights shared with the BRDF's rays (Veach 1997, eq. 9.10, the
// power heuristic). The paths that reach these are in MonteCarloIntegrator.cpp.
#include "glint/sampling/Sampling.hpp"
#include "glint/transport/MonteCarloIntegrator.hpp"
#include "glint/transport/Phong.hpp"

namespace glint {

double MonteCarloIntegrator::EmissionWeight(const Ray& ray, vec3 lightPoint) const {
  using Strategy = MonteCarloOptions::Strategy;
  if (ray.lightCounted) return 0.0;  // next-event estimation counted it
  if (ray.pdf == 0.0) return 1.0;    // camera, mirror and glass directions: nothing else sees it
  switch (options_.strategy) {
    case Strategy::Light:
      return 0.0;
    case Strategy::Brdf:
      return 1.0;
    case Strategy::Mis:
      break;
  }
  return PowerHeuristic(ray.pdf, light_.PdfLi(ray.start, lightPoint));
}

Colour MonteCarloIntegrator::DirectLightPhong(const Hit& hit, vec3 d, vec3 n, double misBranches,
                                              double u, double v, RenderStats& stats,
                                              bool unoccluded) const {
  const Material& m = *hit.material;
  const LightSample ls = light_.SampleLi(hit.point, u, v);
  const double cosTheta = glm::dot(n, ls.wi);
  if (ls.invPdf == 0.0 || cosTheta <= 0.0) return Colour(0.0);
  const PhongValue phong = EvaluatePhong(m, d, n, ls.wi);
  const Colour f = phong.f;
  if (f == Colour(0.0)) return Colour(0.0);
  if (ShadowBlocked(hit.point, n, ls.wi, ls.point, unoccluded, stats)) return Colour(0.0);
  double w = 1.0;
  if (misBranches > 0.0) {  // MIS against `misBranches` BRDF samples
    w = PowerHeuristic(ls.pdf, misBranches * phong.pdf);
  }
  return w * ls.Le * f * (cosTheta * ls.invPdf);
}

}  // namespace glint
