#include "glint/transport/WhittedIntegrator.hpp"

#include <algorithm>
#include <array>

#include "glint/sampling/Sampling.hpp"
#include "glint/transport/Fresnel.hpp"

namespace glint {

namespace {

// CrossDielectric's answer for lane j of the lanes that found it.
DielectricInterface KnownInterface(const SpecularLaneData& lanes, std::size_t j) {
  DielectricInterface glass{std::nullopt, lanes.reflectance[j]};
  if (lanes.refracts[j] != 0.0) {
    glass.refracted = vec3(lanes.refracted[0][j], lanes.refracted[1][j], lanes.refracted[2][j]);
  }
  return glass;
}

}  // namespace

WhittedIntegrator::WhittedIntegrator(const Scene& scene, int maxDepth, FresnelModel fresnel,
                                     std::optional<Pinhole> camera, SimdTarget simd)
    : scene_(scene), maxDepth_(maxDepth), fresnel_(fresnel) {
  if (camera && WhittedWallLanes::Serves(scene_.pointLights)) {
    lanes_.emplace(scene_.wall, scene_.pointLights, *camera, simd);
    hitLanes_.emplace(scene_, *camera, /*withAreaLight=*/false, simd);
    secondaryLanes_.emplace(scene_, /*withAreaLight=*/false, simd);
    localLights_.emplace(scene_, simd);
    specularLanes_.emplace(simd);
  }
}

Colour WhittedIntegrator::TraceFromLane(RayTree& tree, std::uint32_t root, const PixelShaft& shaft,
                                        const RayLanes& lanes, int lane, Sampler& /*sampler*/,
                                        RenderStats& stats) const {
  // Trace's path, from the lanes' hit if they found it.
  Hit hit;
  return TraceNode(tree, root, stats, shaft, hitLanes_->Known(lanes, lane, hit));
}

int WhittedIntegrator::LaneWidth(const PixelShaft& shaft) const {
  if (!lanes_ || !shaft.roomOnly) return 0;
  // LocalLight without its specular lobe, and no children: what the lanes compute.
  const Material& m = scene_.wall.GetMaterial(shaft.side);
  const bool lanesServe = m.type == MaterialType::Lambertian && !(m.whittedSpecular > 0.0);
  return lanesServe ? lanes_->Width() : 0;
}

void WhittedIntegrator::TraceLanes(RayLanes& lanes, int count, const PixelShaft& shaft,
                                   RenderStats& stats) const {
  PointLightLanes lights;
  lanes_->Trace(lanes, count, shaft.side, lights);
  lanes.object = scene_.wall.ObjectOf(shaft.side);
  const vec3 normal = scene_.wall.Face(shaft.side).Normal();
  // LocalLight's sum, per lane: each light the wall faces casts its shadow ray (or the
  // shaft answers it), and adds its term in the lights' order. Counted in a local, which
  // stays in registers (the stats' fields, a lane at a time, are a chain of stores and loads).
  RenderStats counted;
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    const vec3 d(lanes.direction[0][i], lanes.direction[1][i], lanes.direction[2][i]);
    const vec3 p(lanes.end[0][i], lanes.end[1][i], lanes.end[2][i]);
    const vec3 n = FacingNormal(d, normal);
    Colour sum(0.0);
    for (std::size_t j = 0; j < scene_.pointLights.size(); ++j) {
      if (lights.facing[j][i] == 0.0) continue;
      if (!Reaches(j, p, n, shaft, counted)) continue;
      sum += Colour(lights.term[j][0][i], lights.term[j][1][i], lights.term[j][2][i]);
    }
    for (std::size_t c = 0; c < 3; ++c) lanes.colour[c][i] = sum[static_cast<glm::length_t>(c)];
  }
  stats += counted;
}

bool WhittedIntegrator::Reaches(std::size_t i, vec3 p, vec3 n, const PixelShaft& shaft,
                                RenderStats& stats) const {
  ++stats.shadowRays;
  if (shaft.PointLightVisible(static_cast<int>(i))) {
    ++stats.shadowRaysByShaft;  // answered by the pixel's shaft: nothing opaque between
    return true;
  }
  const vec3 position = scene_.pointLights[i].position;
  vec3 l = position - p;  // LocalLight's l, to the bit
  l /= std::sqrt(glm::dot(l, l));
  return scene_.VisibleThroughTransparent(OffsetRayOrigin(p, n, l), position);
}

Colour WhittedIntegrator::Trace(RayTree& tree, std::uint32_t root, const PixelShaft& shaft,
                                Sampler& /*sampler*/, RenderStats& stats) const {
  return TraceNode(tree, root, stats, shaft);
}

Colour WhittedIntegrator::LocalLight(const Hit& hit, vec3 d, RenderStats& stats,
                                     PixelShaft shaft) const {
  const Material& m = *hit.material;
  // Light arrives on the side the ray came from.
  const vec3 n = FacingNormal(d, hit.normal);
  Colour sum(0.0);
  for (std::size_t i = 0; i < scene_.pointLights.size(); ++i) {
    const PointLight& light = scene_.pointLights[i];
    vec3 l = light.position - hit.point;
    const double r2 = glm::dot(l, l);
    l /= std::sqrt(r2);
    const double cosTheta = glm::dot(n, l);
    if (cosTheta <= 0.0) continue;
    if (!Reaches(i, hit.point, n, shaft, stats)) continue;
    const Colour irradiance = light.intensity * (cosTheta / r2);  // E = I cos(theta) / r^2
    double brdf = m.whittedDiffuse * kInvPi;
    if (m.whittedSpecular > 0.0) {
      const double cosR = std::max(0.0, glm::dot(Reflect(-l, n), -d));
      brdf += m.whittedSpecular * (m.exponent + 2.0) / (2.0 * kPi) * CosinePower(cosR, m.exponent);
    }
    sum += m.reflectance * brdf * irradiance;
  }
  return sum;
}

std::uint32_t WhittedIntegrator::SpawnChildren(RayTree& tree, std::uint32_t index, const Hit& hit,
                                               RenderStats& stats, const SpecularLaneData* known,
                                               std::size_t lane) const {
  const Ray parent = tree[index];
  const Material& m = *hit.material;
  const double w = m.WhittedChildWeight();
  if (w <= 0.0) return 0;
  const vec3 d = parent.direction;

  struct Child {
    vec3 direction;
    Colour weight;
    RayKind kind;
    bool inside;
  };
  Child children[2];
  std::uint32_t count = 0;
  const vec3 mirror = known != nullptr ? vec3(known->mirror[0][lane], known->mirror[1][lane],
                                              known->mirror[2][lane])
                                       : glm::normalize(Reflect(d, hit.normal));
  if (m.IsTransparent()) {
    // Fresnel split; F = 1 under total internal reflection. The index ratio flips for
    // rays inside (CrossDielectric sees it from dot(d, n)).
    const DielectricInterface glass =
        known != nullptr ? KnownInterface(*known, lane) : CrossDielectric(d, hit.normal, m.ior);
    const std::optional<vec3>& refracted = glass.refracted;
    const double f = GlassReflectance(glass, m.ior, fresnel_);  // 1 for total internal reflection
    if (f > 0.0) children[count++] = {mirror, Colour(w * f), RayKind::Reflected, parent.inside};
    if (refracted && f < 1.0) {
      children[count++] = {*refracted, Colour(w * (1.0 - f)), RayKind::Refracted, !parent.inside};
    }
  } else {
    // Opaque objects are perfect mirrors in Whitted mode, tinted by their reflectance.
    children[count++] = {mirror, w * m.reflectance, RayKind::Reflected, parent.inside};
  }

  const std::uint32_t first = tree.AddChildren(index, count);
  for (std::uint32_t i = 0; i < count; ++i) {
    Ray& child = tree[first + i];
    child.start = OffsetRayOrigin(hit.point, hit.normal, children[i].direction);
    child.direction = children[i].direction;
    child.weight = children[i].weight;
    child.importance = parent.importance * children[i].weight;
    child.kind = children[i].kind;
    child.inside = children[i].inside;
    child.depth = static_cast<std::uint8_t>(parent.depth + 1);
    if (child.kind == RayKind::Refracted) {
      ++stats.refractedRays;
    } else {
      ++stats.reflectedRays;
    }
  }
  return count;
}

void WhittedIntegrator::FindHit(const RayTree& tree, std::uint32_t index, const PixelShaft& shaft,
                                Hit& hit) const {
  if (shaft.roomOnly) {
    scene_.IntersectRoom(tree[index].start, tree[index].direction, shaft.side, hit);
  } else {
    scene_.Intersect(tree[index].start, tree[index].direction, hit, /*withAreaLight=*/false);
  }
}

std::uint32_t WhittedIntegrator::ShadeNode(RayTree& tree, std::uint32_t index, const Hit& hit,
                                           Colour& local, RenderStats& stats,
                                           const PixelShaft& shaft, const Colour* knownLocal,
                                           const SpecularLaneData* known, std::size_t lane) const {
  if (!(hit.t < kInfinity)) {
    // Left the room through the open front: radiance 0.
    tree[index].final = true;
    tree[index].end = tree[index].start;
    tree[index].colour = Colour(0.0);
    local = Colour(0.0);
    return 0;
  }
  tree[index].end = hit.point;
  tree[index].object = hit.object;
  local =
      knownLocal != nullptr ? *knownLocal : LocalLight(hit, tree[index].direction, stats, shaft);
  // Walls spawn nothing; the depth limit counts ray iterations, the camera ray being
  // the first.
  std::uint32_t count = 0;
  if (hit.material->type != MaterialType::Lambertian && tree[index].depth + 1 < maxDepth_) {
    count = SpawnChildren(tree, index, hit, stats, known, lane);
  }
  tree[index].final = count == 0;
  tree[index].colour = local;
  return count;
}

Colour WhittedIntegrator::TraceNode(RayTree& tree, std::uint32_t index, RenderStats& stats,
                                    PixelShaft shaft, const Hit* known) const {
  Hit hit;
  if (known != nullptr) {
    hit = *known;
  } else {
    FindHit(tree, index, shaft, hit);
  }
  Colour colour;
  const std::uint32_t count = ShadeNode(tree, index, hit, colour, stats, shaft);
  const std::uint32_t first = tree[index].firstChild;
  for (std::uint32_t i = 0; i < count; ++i) {
    const Colour c = TraceNode(tree, first + i, stats);
    colour += tree[first + i].weight * c;  // C_R = L_local + sum W_i C_i
  }
  tree[index].colour = colour;
  return colour;
}

void WhittedIntegrator::ShadeBatch(RayTree& trees, std::uint32_t first, int n, const Hit* hits,
                                   const PixelShaft& shaft, LocalLightLaneData& lights,
                                   SpecularLaneData& specular, RenderStats& stats) const {
  // The local terms in lanes, where every light's shadow ray is cast (the shaft knows no
  // light visible) and the material's lobe is one the lanes raise by squaring.
  const bool inLanes = shaft.pointLightsVisible == 0;
  std::array<int, RayLanes::kMax> laneOf{};  // its lane in `lights`, or -1
  int inLaneCount = 0;
  for (int j = 0; j < n; ++j) {
    const auto lane = static_cast<std::size_t>(j);
    const Hit& hit = hits[lane];
    laneOf[lane] = -1;
    if (!inLanes || !(hit.t < kInfinity) || !LocalLightLanes::Serves(*hit.material)) continue;
    const auto k = static_cast<std::size_t>(inLaneCount);
    const vec3 d = trees[first + static_cast<std::uint32_t>(j)].direction;
    const vec3 normal = FacingNormal(d, hit.normal);
    for (std::size_t a = 0; a < 3; ++a) {
      const auto c = static_cast<glm::length_t>(a);
      lights.point[a][k] = hit.point[c];
      lights.normal[a][k] = normal[c];
      lights.direction[a][k] = d[c];
    }
    LocalLightLanes::SetMaterial(lights, k, *hit.material);
    laneOf[lane] = inLaneCount++;
  }
  if (inLaneCount > 0) localLights_->Shade(lights, inLaneCount);
  // The children's directions too, for every hit that will spawn (lane j's in lane j).
  bool spawns = false;
  for (int j = 0; j < n; ++j) {
    const auto lane = static_cast<std::size_t>(j);
    const Hit& hit = hits[lane];
    const Ray& ray = trees[first + static_cast<std::uint32_t>(j)];
    const bool spawning = hit.t < kInfinity && hit.material->type != MaterialType::Lambertian &&
                          ray.depth + 1 < maxDepth_;
    for (std::size_t a = 0; a < 3; ++a) {
      const auto c = static_cast<glm::length_t>(a);
      specular.direction[a][lane] = ray.direction[c];
      specular.normal[a][lane] = spawning ? hit.normal[c] : 0.0;
    }
    specular.ior[lane] = spawning ? hit.material->ior : 1.0;
    spawns = spawns || spawning;
  }
  if (spawns) specularLanes_->Find(specular, n);
  Colour local;
  for (int j = 0; j < n; ++j) {
    const auto lane = static_cast<std::size_t>(j);
    const std::uint32_t index = first + static_cast<std::uint32_t>(j);
    const SpecularLaneData* directions = spawns ? &specular : nullptr;
    if (laneOf[lane] < 0) {
      ShadeNode(trees, index, hits[lane], local, stats, shaft, nullptr, directions, lane);
      continue;
    }
    const auto k = static_cast<std::size_t>(laneOf[lane]);
    const Colour known(lights.colour[0][k], lights.colour[1][k], lights.colour[2][k]);
    stats.shadowRays += static_cast<std::uint64_t>(lights.shadowRays[k]);
    ShadeNode(trees, index, hits[lane], local, stats, shaft, &known, directions, lane);
  }
}

void WhittedIntegrator::TraceGroupFromLanes(RayTree& trees, std::uint32_t firstRoot, int count,
                                            const PixelShaft& shaft, const RayLanes* laneSets,
                                            Sampler& /*sampler*/, int /*firstSample*/,
                                            const Sampler::FirstGroups* /*groups*/,
                                            RenderStats& stats, Colour* colours) const {
  std::array<Hit, RayLanes::kMax> hits;
  LocalLightLaneData lights;
  SpecularLaneData specular;
  // The camera rays, kMax at a time, from the first-hit lanes' hits (or Scene::Intersect's,
  // where the lanes handed a ray back), with what the pixel's shaft knows.
  for (int setFirst = 0; setFirst < count; setFirst += RayLanes::kMax) {
    const RayLanes& lanes = laneSets[static_cast<std::size_t>(setFirst / RayLanes::kMax)];
    const int n = std::min(RayLanes::kMax, count - setFirst);
    const std::uint32_t first = firstRoot + static_cast<std::uint32_t>(setFirst);
    for (int lane = 0; lane < n; ++lane) {
      Hit& hit = hits[static_cast<std::size_t>(lane)];
      if (hitLanes_->Known(lanes, lane, hit) == nullptr) {
        FindHit(trees, first + static_cast<std::uint32_t>(lane), shaft, hit);
      }
    }
    ShadeBatch(trees, first, n, hits.data(), shaft, lights, specular, stats);
  }
  // Then a level at a time: the children a level makes are the next level, contiguous
  // in the arena after it, and their hits are found W at a time.
  RayLanes level{};
  auto begin = static_cast<std::uint32_t>(firstRoot + static_cast<std::uint32_t>(count));
  while (begin < trees.Size()) {
    const auto end = static_cast<std::uint32_t>(trees.Size());
    for (std::uint32_t first = begin; first < end; first += RayLanes::kMax) {
      const int n = static_cast<int>(std::min<std::uint32_t>(RayLanes::kMax, end - first));
      for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
        const Ray& ray = trees[first + static_cast<std::uint32_t>(j)];
        for (std::size_t a = 0; a < 3; ++a) {
          level.start[a][j] = ray.start[static_cast<glm::length_t>(a)];
          level.direction[a][j] = ray.direction[static_cast<glm::length_t>(a)];
        }
      }
      secondaryLanes_->Trace(level, n);
      for (int j = 0; j < n; ++j) {
        const auto lane = static_cast<std::size_t>(j);
        if (level.closest[lane] < 0.0) {
          FindHit(trees, first + static_cast<std::uint32_t>(j), PixelShaft{}, hits[lane]);
        } else {
          secondaryLanes_->FillHit(level, j, hits[lane]);
        }
      }
      ShadeBatch(trees, first, n, hits.data(), PixelShaft{}, lights, specular, stats);
    }
    begin = end;
  }
  trees.AddChildColours(firstRoot);  // in TraceNode's order
  for (int lane = 0; lane < count; ++lane) {
    colours[lane] = trees[firstRoot + static_cast<std::uint32_t>(lane)].colour;
  }
}

}  // namespace glint
