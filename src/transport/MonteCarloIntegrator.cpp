#include "glint/transport/MonteCarloIntegrator.hpp"

#include <array>
#include <stdexcept>

#include "glint/sampling/Sampling.hpp"
#include "glint/transport/Fresnel.hpp"
#include "glint/transport/Phong.hpp"

namespace glint {

namespace {
const Light& RequireLight(const Scene& scene) {
  if (!scene.light)
    throw std::invalid_argument("Monte Carlo mode needs an area_light in the scene");
  return *scene.light;
}
}  // namespace

MonteCarloIntegrator::MonteCarloIntegrator(const Scene& scene, MonteCarloOptions options,
                                           std::optional<Pinhole> camera)
    : scene_(scene),
      light_(RequireLight(scene)),
      options_(options),
      mirrored_(scene, light_),
      useMirrored_(options.walls == MonteCarloOptions::Walls::Diffuse &&
                   options.mirrorLight == MonteCarloOptions::MirrorLight::Nee &&
                   !mirrored_.Empty()) {
  if (options_.branches < 1 || options_.branches > kMaxBranches) {
    throw std::invalid_argument("branches must be in [1, 64]");
  }
  if (!(options_.rouletteThreshold > 0.0)) {
    throw std::invalid_argument("the roulette threshold must be positive");
  }
  if (options_.caustics == MonteCarloOptions::Caustics::Light) {
    if (options_.walls != MonteCarloOptions::Walls::Diffuse) {
      throw std::invalid_argument("caustics by light tracing need diffuse walls");
    }
    if (!camera) throw std::invalid_argument("caustics by light tracing need the camera");
    tracer_.emplace(scene_, light_, options_, *camera, !useMirrored_);
  }
  if (camera) {
    if (options_.walls == MonteCarloOptions::Walls::Terminal) {
      lanes_.emplace(scene_.wall, light_, *camera, options_.simd);
    }
    hitLanes_.emplace(scene_, *camera, /*withAreaLight=*/true, options_.simd);
    secondaryLanes_.emplace(scene_, /*withAreaLight=*/true, options_.simd);
    wallLightLanes_.emplace(scene_, light_, options_.simd);
    wallChildLanes_.emplace(options_.simd);
  }
}

Colour MonteCarloIntegrator::TraceFromLane(RayTree& tree, std::uint32_t root,
                                           const PixelShaft& shaft, const RayLanes& lanes, int lane,
                                           Sampler& sampler, RenderStats& stats) const {
  // A pixel that is not roomOnly (FirstHitLanes): Trace's path, from the lanes' hit if known.
  Hit hit;
  return TraceNode(tree, root, root, sampler, stats, shaft, hitLanes_->Known(lanes, lane, hit));
}

void MonteCarloIntegrator::TraceGroupFromLanes(RayTree& trees, std::uint32_t firstRoot, int count,
                                               const PixelShaft& shaft, const RayLanes* lanes,
                                               Sampler& sampler, int firstSample,
                                               const Sampler::FirstGroups* groups,
                                               RenderStats& stats, Colour* colours) const {
  constexpr std::size_t kSlots = RayLanes::kMax;
  // A slot traces one path at a time, in a sampler of its own (a sample's numbers depend
  // on its index and dimensions alone, Sobol's padding on a stream of the sample's own),
  // and takes the group's next camera ray when its path ends, so the lanes stay full.
  std::array<Sampler, kSlots> samplers{sampler, sampler, sampler, sampler,
                                       sampler, sampler, sampler, sampler};
  // A slot's rays still to trace, last on top, with their node numbers: the stack
  // TraceNode's recursion keeps, so the path's tree is visited in the same order.
  struct Pending {
    std::uint32_t index, node;
  };
  std::array<std::array<Pending, kGroupStack>, kSlots> stacks;
  std::array<int, kSlots> top{};
  std::array<std::uint32_t, kSlots> nodes{};  // the slot's tree's nodes so far
  std::array<std::uint32_t, kSlots> roots{};
  // The wall hits' next-event estimates and children, W at a time in lanes
  // (LambertianLightLanes, LambertianScatterLanes).
  WallLaneWork walls;
  const auto shade = [&](std::size_t slot, Pending p, const Hit& hit, const PixelShaft& s) {
    Colour local;
    const std::uint32_t kept = ShadeNode(trees, p.index, p.node, roots[slot], hit, local,
                                         samplers[slot], stats, s, &walls);
    if (walls.lights.count == RayLanes::kMax) FlushWallLights(trees, walls.lights, stats);
    if (walls.children.count == RayLanes::kMax) FlushWallChildren(trees, walls.children);
    const std::uint32_t first = trees[p.index].firstChild;
    for (std::uint32_t i = kept; i-- > 0;) {
      stacks[slot][static_cast<std::size_t>(top[slot]++)] = {first + i, nodes[slot] + i};
    }
    nodes[slot] += kept;
  };
  // A free slot starts the next camera rays, from the first-hit lanes' hits (or FindHit's,
  // where the lanes handed a ray back), with what the pixel's shaft knows, until one goes on.
  int next = 0;
  std::size_t lastSlot = 0;  // the slot of the group's last ray
  const auto refill = [&](std::size_t slot) {
    while (top[slot] == 0 && next < count) {
      const int i = next++;
      const auto set = static_cast<std::size_t>(i / RayLanes::kMax);
      const int lane = i % RayLanes::kMax;
      samplers[slot].StartSampleWith(firstSample + i, groups[set], static_cast<std::size_t>(lane));
      roots[slot] = firstRoot + static_cast<std::uint32_t>(i);
      Hit hit;
      if (hitLanes_->Known(lanes[set], lane, hit) == nullptr) {
        FindHit(trees[roots[slot]], shaft, hit);
      }
      nodes[slot] = 1;
      lastSlot = slot;
      shade(slot, {roots[slot], 0}, hit, shaft);
    }
  };
  // Then a step at a time: the next ray of every slot whose path goes on.
  RayLanes step{};
  std::array<std::size_t, kSlots> slotOf{};
  std::array<Pending, kSlots> pending{};
  for (;;) {
    int n = 0;
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
      refill(slot);
      if (top[slot] == 0) continue;
      const auto j = static_cast<std::size_t>(n++);
      slotOf[j] = slot;
      pending[j] = stacks[slot][static_cast<std::size_t>(--top[slot])];
    }
    if (n == 0) break;
    FlushWallChildren(trees, walls.children);  // some of the rays just taken wait there
    for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
      const Ray& ray = trees[pending[j].index];
      for (std::size_t a = 0; a < 3; ++a) {
        step.start[a][j] = ray.start[static_cast<glm::length_t>(a)];
        step.direction[a][j] = ray.direction[static_cast<glm::length_t>(a)];
      }
    }
    secondaryLanes_->Trace(step, n);
    for (int j = 0; j < n; ++j) {
      const auto k = static_cast<std::size_t>(j);
      Hit hit;
      if (step.closest[k] < 0.0) {
        FindHit(trees[pending[k].index], PixelShaft{}, hit);
      } else {
        secondaryLanes_->FillHit(step, j, hit);
      }
      shade(slotOf[k], pending[k], hit, PixelShaft{});
    }
  }
  FlushWallLights(trees, walls.lights, stats);
  trees.AddChildColours(firstRoot);  // in TraceNode's order
  for (int i = 0; i < count; ++i)
    colours[i] = trees[firstRoot + static_cast<std::uint32_t>(i)].colour;
  sampler = samplers[lastSlot];
}

void MonteCarloIntegrator::FlushWallLights(RayTree& trees, LambertianLightLaneData& deferred,
                                           RenderStats& stats) const {
  if (deferred.count == 0) return;
  wallLightLanes_->Estimate(deferred);
  std::uint64_t cast = 0;
  std::uint64_t byShaft = 0;
  for (std::size_t j = 0; j < static_cast<std::size_t>(deferred.count); ++j) {
    Ray& ray = trees[deferred.node[j]];
    const Colour direct(deferred.colour[0][j], deferred.colour[1][j], deferred.colour[2][j]);
    ray.colour = direct + ray.colour;  // ShadeNode's (0 + direct) + rest, to the bit
    if (deferred.cast[j] != 0.0) {
      ++cast;
      if (deferred.unoccluded[j] != 0.0) ++byShaft;
    }
  }
  stats.shadowRays += cast;
  stats.shadowRaysByShaft += byShaft;
  deferred.count = 0;
}

void MonteCarloIntegrator::FlushWallChildren(RayTree& trees,
                                             LambertianScatterLaneData& deferred) const {
  if (deferred.count == 0) return;
  wallChildLanes_->Sample(deferred);
  for (std::size_t j = 0; j < static_cast<std::size_t>(deferred.count); ++j) {
    Ray& ray = trees[deferred.node[j]];
    ray.start = vec3(deferred.start[0][j], deferred.start[1][j], deferred.start[2][j]);
    ray.direction =
        vec3(deferred.direction[0][j], deferred.direction[1][j], deferred.direction[2][j]);
  }
  deferred.count = 0;
}

void MonteCarloIntegrator::TraceLanes(RayLanes& lanes, int count, const PixelShaft& shaft,
                                      RenderStats& stats) const {
  lanes_->Trace(lanes, count, shaft.side);
  lanes.object = scene_.wall.ObjectOf(shaft.side);
  // The shadow rays, per lane: counted, and tested where the shaft did not answer them
  // (ShadowBlocked, with the scalar code's inputs: the same bits).
  if (shaft.areaLightVisible) {  // the shaft answers them all: only counted
    std::uint64_t lit = 0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
      lit += lanes.lit[i] != 0.0 ? 1U : 0U;
    }
    stats.shadowRays += lit;
    stats.shadowRaysByShaft += lit;
    return;
  }
  const vec3 normal = scene_.wall.Face(shaft.side).Normal();
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    if (lanes.lit[i] == 0.0) continue;
    const vec3 d(lanes.direction[0][i], lanes.direction[1][i], lanes.direction[2][i]);
    const vec3 p(lanes.end[0][i], lanes.end[1][i], lanes.end[2][i]);
    const vec3 y(lanes.lightPoint[0][i], lanes.lightPoint[1][i], lanes.lightPoint[2][i]);
    if (ShadowBlocked(p, FacingNormal(d, normal), y - p, y, shaft.areaLightVisible, stats)) {
      for (auto& c : lanes.colour) c[i] = 0.0;
    }
  }
}

Colour MonteCarloIntegrator::Trace(RayTree& tree, std::uint32_t root, const PixelShaft& shaft,
                                   Sampler& sampler, RenderStats& stats) const {
  if (shaft.roomOnly && options_.walls == MonteCarloOptions::Walls::Terminal) {
    // Four camera rays in five: the pixel's shaft holds only the room, so the ray ends
    // on a known wall and spawns nothing. None of TraceNode's machinery is needed.
    Ray& ray = tree[root];
    Hit hit;
    scene_.IntersectRoom(ray.start, ray.direction, shaft.side, hit);
    ray.end = hit.point;
    ray.object = hit.object;
    return EndAtTerminalWall(ray, hit, FacingNormal(ray.direction, hit.normal), 0, sampler, stats,
                             shaft.areaLightVisible);
  }
  return TraceNode(tree, root, root, sampler, stats, shaft);
}

Colour MonteCarloIntegrator::EndAtTerminalWall(Ray& ray, const Hit& hit, vec3 n, std::uint32_t node,
                                               Sampler& sampler, RenderStats& stats,
                                               bool unoccluded) const {
  const Colour colour = DirectLight(hit, ray.direction, n, 0.0,
                                    sampler.Get2D(SampleDimension::Light(node)), stats, unoccluded);
  ray.final = true;
  ray.colour = colour;
  return colour;
}

int MonteCarloIntegrator::Scatter(const Ray& ray, const Hit& hit, vec3 n, std::uint32_t node,
                                  Sampler& sampler, Candidate* out,
                                  LambertianScatterLaneData* deferred) const {
  const Material& m = *hit.material;
  const vec3 d = ray.direction;
  switch (m.type) {
    case MaterialType::Lambertian: {
      if (options_.walls == MonteCarloOptions::Walls::Terminal) return 0;
      // Cosine sampling: f cos / p = (rho / pi) cos / (cos / pi) = rho.
      const Sample2 uv = sampler.Get2D(SampleDimension::Scatter(node));
      vec3 w(0.0);  // with `deferred`, LambertianScatterLanes computes it
      if (deferred != nullptr) {
        deferred->Stage(hit.point, hit.normal, n, uv);
      } else {
        w = SampleCosineDirection(n, uv.u, uv.v);
      }
      // The light it may reach: counted by next-event estimation at this wall.
      out[0] = Candidate::Of(w, m.reflectance, 0.0, RayKind::Diffuse, ray.inside, true);
      return 1;
    }
    case MaterialType::Phong: {
      const int k = options_.branches;
      for (int i = 0; i < k; ++i) {
        const Sample2 uv =
            sampler.Get2D(i == 0 ? SampleDimension::Scatter(node)
                                 : SampleDimension::Extra(node, static_cast<std::uint32_t>(i)));
        const PhongSample s = SamplePhong(m, d, n, uv.u, uv.v);
        out[i] = Candidate::Of(s.direction, s.weight / static_cast<double>(k), k * s.pdf,
                               RayKind::Reflected, ray.inside);
      }
      return k;
    }
    case MaterialType::Mirror: {
      // A perfect mirror reflects rho at every angle (spec, "Objects"), as Whitted's
      // mirror and Cycles' sharp Glossy BSDF do. (The normalised Phong lobe's n -> infinity
      // limit is not this mirror: its albedo tends to rho cos(theta).)
      // The light it reaches after a diffuse ray: MirroredLight counted it at that ray's wall.
      const vec3 r = glm::normalize(Reflect(d, n));
      const bool counted = useMirrored_ && ray.kind == RayKind::Diffuse;
      out[0] = Candidate::Of(r, m.reflectance, 0.0, RayKind::Reflected, ray.inside, counted);
      return 1;
    }
    case MaterialType::Glass: {
      const vec3 mirror = glm::normalize(Reflect(d, hit.normal));
      const DielectricInterface glass = CrossDielectric(d, hit.normal, m.ior);
      const std::optional<vec3>& refracted = glass.refracted;
      const double f = GlassReflectance(glass, m.ior, options_.fresnel);
      if (options_.glass == MonteCarloOptions::Glass::Choose) {
        // One child, reflection with probability F: weight F / F = (1 - F) / (1 - F) = 1.
        if (!refracted || sampler.Get1D(SampleDimension::Choice(node)) < f) {
          out[0] = Candidate::Of(mirror, Colour(1.0), 0.0, RayKind::Reflected, ray.inside);
        } else {
          out[0] = Candidate::Of(*refracted, Colour(1.0), 0.0, RayKind::Refracted, !ray.inside);
        }
        return 1;
      }
      int count = 0;
      if (f > 0.0) {
        out[count++] = Candidate::Of(mirror, Colour(f), 0.0, RayKind::Reflected, ray.inside);
      }
      if (refracted && f < 1.0) {
        out[count++] =
            Candidate::Of(*refracted, Colour(1.0 - f), 0.0, RayKind::Refracted, !ray.inside);
      }
      return count;
    }
  }
  return 0;
}

void MonteCarloIntegrator::SetCausticRatios(const Ray& ray, const Hit& hit, vec3 n,
                                            Candidate* candidates, int count) const {
  switch (hit.material->type) {
    case MaterialType::Lambertian:
      // A wall the camera sees: its cosine-sampled ray may find a caustic path, which the
      // light's paths find too (LightTracer.hpp); deeper walls pass r on unchanged (the
      // cosine densities of the two sides are equal in projected solid angle).
      if (count > 0) {
        candidates[0].causticRatio =
            ray.kind == RayKind::Camera ? tracer_->CameraRatio(hit.point, n) : ray.causticRatio;
      }
      return;
    case MaterialType::Mirror:
    case MaterialType::Glass:
      for (int i = 0; i < count; ++i) candidates[i].causticRatio = ray.causticRatio;
      return;
    case MaterialType::Phong: {
      if (ray.causticRatio == 0.0) return;
      const double cosEye = -glm::dot(n, ray.direction);
      for (int i = 0; i < count; ++i) {
        const double cosLight = glm::dot(n, candidates[i].direction);
        if (cosLight > 0.0) {
          candidates[i].causticRatio =
              ray.causticRatio * LightTracer::PhongFactor(cosLight, cosEye, options_.branches);
        }
      }
      return;
    }
  }
}

void MonteCarloIntegrator::FindHit(const Ray& ray, const PixelShaft& shaft, Hit& hit) const {
  if (shaft.roomOnly) {
    scene_.IntersectRoom(ray.start, ray.direction, shaft.side, hit);
  } else {
    scene_.Intersect(ray.start, ray.direction, hit, /*withAreaLight=*/true);
  }
}

Colour MonteCarloIntegrator::TraceNode(RayTree& tree, std::uint32_t index, std::uint32_t root,
                                       Sampler& sampler, RenderStats& stats, PixelShaft shaft,
                                       const Hit* known) const {
  Hit hit;
  if (known != nullptr) {
    hit = *known;
  } else {
    FindHit(tree[index], shaft, hit);
  }
  Colour colour;
  const std::uint32_t kept =
      ShadeNode(tree, index, index - root, root, hit, colour, sampler, stats, shaft);
  const std::uint32_t first = tree[index].firstChild;
  for (std::uint32_t i = 0; i < kept; ++i) {
    const Colour c = TraceNode(tree, first + i, root, sampler, stats);
    colour += tree[first + i].weight * c;  // C_R = L_local + sum W_i C_i
  }
  tree[index].colour = colour;
  return colour;
}

std::uint32_t MonteCarloIntegrator::ShadeNode(RayTree& tree, std::uint32_t index,
                                              std::uint32_t node, std::uint32_t root,
                                              const Hit& hit, Colour& local, Sampler& sampler,
                                              RenderStats& stats, const PixelShaft& shaft,
                                              WallLaneWork* deferred) const {
  // A reference, not a copy (copying the node cost ~10% of the render): valid until
  // AddChildren below may move the nodes; what is needed after that is read first.
  const Ray& ray = tree[index];
  if (!(hit.t < kInfinity)) {
    tree[index].end = ray.start;
    tree[index].final = true;  // out through the open front: radiance 0
    tree[index].colour = Colour(0.0);
    local = Colour(0.0);
    return 0;
  }
  tree[index].end = hit.point;
  tree[index].object = hit.object;
  if (hit.light) {  // the light emits and reflects nothing
    const Colour c = EmissionWeight(ray, hit.point) * light_.Le(-ray.direction);
    tree[index].final = true;
    tree[index].colour = c;
    local = c;
    return 0;
  }
  const Material& m = *hit.material;
  const vec3 n = FacingNormal(ray.direction, hit.normal);
  Colour colour(0.0);
  // Next-event estimation at walls (always) and Phong objects (unless BRDF-only).
  using Strategy = MonteCarloOptions::Strategy;
  if (m.type == MaterialType::Lambertian) {
    if (deferred != nullptr) {
      deferred->lights.Add(index, hit.point, n, light_.Radiance() * m.reflectance,
                           sampler.Get2D(SampleDimension::Light(node)), shaft.areaLightVisible);
    }
    // The design's terminal walls end most paths: no child, nothing else to do.
    if (options_.walls == MonteCarloOptions::Walls::Terminal) {
      if (deferred == nullptr) {
        local =
            EndAtTerminalWall(tree[index], hit, n, node, sampler, stats, shaft.areaLightVisible);
      } else {
        tree[index].final = true;
        tree[index].colour = Colour(0.0);
        local = Colour(0.0);
      }
      return 0;
    }
    if (deferred == nullptr) {
      colour += DirectLight(hit, ray.direction, n, 0.0, sampler.Get2D(SampleDimension::Light(node)),
                            stats, shaft.areaLightVisible);
    }
    // And the light seen in the mirrors, estimated at a wall hit with probability
    // kMirroredLightProbability (and divided by it).
    if (useMirrored_ &&
        sampler.Get1D(SampleDimension::MirroredLight(node) + 2) < kMirroredLightProbability) {
      const Sample2 uv = sampler.Get2D(SampleDimension::MirroredLight(node));
      colour += m.reflectance * (kInvPi / kMirroredLightProbability) *
                mirrored_.Irradiance(hit.point, n, uv.u, uv.v, stats);
    }
  } else if (m.type == MaterialType::Phong && options_.strategy != Strategy::Brdf) {
    const double misBranches =
        options_.strategy == Strategy::Mis ? static_cast<double>(options_.branches) : 0.0;
    colour +=
        DirectLight(hit, ray.direction, n, misBranches, sampler.Get2D(SampleDimension::Light(node)),
                    stats, false, ray.causticRatio);
  }

  // Read late: the node was written just before this call, and a load right after
  // the store stalls (measured).
  const Colour importance = ray.importance;
  const int depth = ray.depth;
  Candidate candidates[kMaxBranches];
  int count = depth + 1 < options_.maxDepth
                  ? Scatter(ray, hit, n, node, sampler, candidates,
                            deferred != nullptr ? &deferred->children : nullptr)
                  : 0;
  if (tracer_) SetCausticRatios(ray, hit, n, candidates, count);
  // Russian roulette by throughput relative to the camera ray, whose importance is
  // 1/N: survive with q = min(1, beta / threshold), then divide by q. (The root
  // is read here, not before tracing: a load right after the store that wrote it stalls.)
  const double rootImportance = count > 0 ? MaxComponent(tree[root].importance) : 0.0;
  const double rootScale = rootImportance > 0.0 ? 1.0 / rootImportance : 1.0;
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    Candidate c = candidates[i];
    const double beta = MaxComponent(importance * c.weight) * rootScale;
    if (!(beta > 0.0)) continue;
    const double q = beta / options_.rouletteThreshold;
    if (q < 1.0) {
      const std::uint32_t dimension =
          i == 0 ? SampleDimension::Roulette(node)
                 : SampleDimension::Extra(node, static_cast<std::uint32_t>(i)) + 2;
      if (sampler.Get1D(dimension) >= q) continue;
      c.weight /= q;
    }
    candidates[kept++] = c;
  }
  const std::uint32_t first =
      kept > 0 ? tree.AddChildren(index, static_cast<std::uint32_t>(kept)) : 0;
  for (int i = 0; i < kept; ++i) {
    const Candidate& c = candidates[i];
    Ray& child = tree[first + static_cast<std::uint32_t>(i)];
    if (deferred != nullptr && c.kind == RayKind::Diffuse) {
      deferred->children.Keep(first + static_cast<std::uint32_t>(i));  // its ray: in lanes
    } else {
      child.start = OffsetRayOrigin(hit.point, hit.normal, c.direction);  // the side it leaves on
      child.direction = c.direction;
    }
    child.weight = c.weight;
    child.importance = importance * c.weight;
    child.pdf = c.pdf;
    child.kind = c.kind;
    child.inside = c.inside;
    child.lightCounted = c.lightCounted;
    child.causticRatio = c.causticRatio;
    child.depth = static_cast<std::uint8_t>(depth + 1);
    switch (c.kind) {
      case RayKind::Refracted:
        ++stats.refractedRays;
        break;
      case RayKind::Diffuse:
        ++stats.diffuseRays;
        break;
      default:
        ++stats.reflectedRays;
        break;
    }
  }
  tree[index].final = kept == 0;
  tree[index].colour = colour;
  local = colour;
  return static_cast<std::uint32_t>(kept);
}
}  // namespace glint
