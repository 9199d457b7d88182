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
  // r = p_t1 / p_s0 of a caustic path that light tracing finds too (LightTracer.hpp).
  const double r = ray.causticRatio;
  if (ray.pdf == 0.0) {
    // Camera, mirror and glass directions: only light tracing sees these paths too.
    return r == 0.0 ? 1.0 : 1.0 / (1.0 + r * r);
  }
  switch (options_.strategy) {
    case Strategy::Light:
      return 0.0;
    case Strategy::Brdf:
      return r == 0.0 ? 1.0 : 1.0 / (1.0 + r * r);
    case Strategy::Mis:
      break;
  }
  const double pdfLi = light_.PdfLi(ray.start, lightPoint);
  if (r == 0.0) return PowerHeuristic(ray.pdf, pdfLi);
  const double s1 = pdfLi / ray.pdf;  // next-event estimation's p_s1 / p_s0
  return 1.0 / (1.0 + s1 * s1 + r * r);
}

Colour MonteCarloIntegrator::DirectLightPhong(const Hit& hit, vec3 d, vec3 n, double misBranches,
                                              double u, double v, RenderStats& stats,
                                              bool unoccluded, double causticRatio) const {
  const Material& m = *hit.material;
  const LightSample ls = light_.SampleLi(hit.point, u, v);
  const double cosTheta = glm::dot(n, ls.wi);
  if (ls.invPdf == 0.0 || cosTheta <= 0.0) return Colour(0.0);
  const PhongValue phong = EvaluatePhong(m, d, n, ls.wi);
  const Colour f = phong.f;
  if (f == Colour(0.0)) return Colour(0.0);
  if (ShadowBlocked(hit.point, n, ls.wi, ls.point, unoccluded, stats)) return Colour(0.0);
  double w = 1.0;
  if (causticRatio > 0.0) {
    // Against the BRDF's samples and light tracing (LightTracer.hpp): p_s0 / p_s1 and
    // p_t1 / p_s1 = r (p_s1 / p_s0)^-1 with r's Phong factor for this direction.
    const double s0 = misBranches * phong.pdf / ls.pdf;
    const double t1 = causticRatio * phong.pdf * cosTheta / (-glm::dot(n, d) * ls.pdf);
    w = 1.0 / (1.0 + s0 * s0 + t1 * t1);
  } else if (misBranches > 0.0) {  // MIS against `misBranches` BRDF samples
    w = PowerHeuristic(ls.pdf, misBranches * phong.pdf);
  }
  return w * ls.Le * f * (cosTheta * ls.invPdf);
}

}  // namespace glint
