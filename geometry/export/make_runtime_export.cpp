#include "geometry/export/runtime_export.h"

#include "geometry/export/kept_box.h"
#include "geometry/export/unit_transform.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>

namespace probeproxy {

namespace {

bool isFinite(glm::dvec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isFinite(const glm::dquat& q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

bool isPositive(glm::dvec3 v) { return v.x > 0.0 && v.y > 0.0 && v.z > 0.0; }

[[noreturn]] void failShape(const std::string& probe, const std::string& problem) {
  throw std::invalid_argument("runtime export: probe '" + probe + "': " + problem);
}

// The build is ours, not the user's: a broken shape is a bug upstream, not bad input.
void checkShape(const std::string& probe, const ProxyShape& shape) {
  if (const auto* k = std::get_if<CheapKShape>(&shape)) {
    if (!std::isfinite(k->kPerMeter)) failShape(probe, "cheap_k with a non-finite k");
  } else if (const auto* box = std::get_if<BoxShape>(&shape)) {
    if (!isFinite(box->centerMeters) || !isPositive(box->halfExtentsMeters) ||
        !isFinite(box->halfExtentsMeters) || !isFinite(box->worldFromBox)) {
      failShape(probe, "box with a non-finite or empty extent");
    }
  } else if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    if (!isFinite(sphere->centerMeters) || !isPositive(sphere->radiiMeters) ||
        !isFinite(sphere->radiiMeters) || !isFinite(sphere->worldFromSphere)) {
      failShape(probe, "sphere with a non-finite or empty radius");
    }
  } else if (const auto* convex = std::get_if<ConvexProxy>(&shape)) {
    if (convex->planes.empty()) failShape(probe, "convex proxy without planes");
    for (const ProxyPlane& p : convex->planes) {
      if (!isFinite(p.normal) || !std::isfinite(p.offsetMeters)) {
        failShape(probe, "convex proxy with a non-finite plane");
      }
    }
    for (const glm::dvec3& v : convex->verticesMeters) {
      if (!isFinite(v)) failShape(probe, "convex proxy with a non-finite vertex");
    }
    for (const glm::uvec3& t : convex->triangles) {
      if (t.x >= convex->verticesMeters.size() || t.y >= convex->verticesMeters.size() ||
          t.z >= convex->verticesMeters.size()) {
        failShape(probe, "convex proxy with a triangle index out of range");
      }
    }
  }
}

// Lowest p95 among the candidates `accepts` takes; unmeasured (NaN) last, ties to the first.
std::optional<std::size_t> bestCandidate(const std::vector<ProxyCandidate>& candidates,
                                         const std::function<bool(const ProxyShape&)>& accepts) {
  std::optional<std::size_t> best;
  const auto p95 = [&](std::size_t i) {
    const double v = candidates[i].error.p95Deg;
    return std::isnan(v) ? INFINITY : v;
  };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!accepts(candidates[i].shape)) continue;
    if (!best || p95(i) < p95(*best)) best = i;
  }
  return best;
}

// A box no engine could take (flat: see holdsVolume) is not offered to any.
bool isAabb(const ProxyShape& s) { return methodOf(s) == Method::Aabb && holdsVolume(s); }
bool isBox(const ProxyShape& s) { return std::holds_alternative<BoxShape>(s) && holdsVolume(s); }
bool isTrueSphere(const ProxyShape& s) {
  const auto* sphere = std::get_if<SphereShape>(&s);
  return sphere && sphere->radiiMeters.x == sphere->radiiMeters.y &&
         sphere->radiiMeters.y == sphere->radiiMeters.z && holdsVolume(s);
}

EngineSource sourceOf(const ProxyCandidate& c, bool keptProxy) {
  return {candidateName(c), c.error, keptProxy};
}

// The kept proxy when it is a box (keptBox: a BoxShape, or a convex within 1 um of one), so
// the engine gets what was measured; Unity, which ignores rotation, only when it is an `aabb`.
// Otherwise the candidate of the kind the engine takes with the lowest p95, marked as not the
// kept proxy: its `error` beside the probe's own says what the engine loses.
// The influence with its fade scaled: inner = outer - scale * (outer - inner), per axis.
InfluenceVolume scaledFade(const InfluenceVolume& influence, double scale) {
  if (scale == 1.0) return influence;  // exactly: outer - (outer - inner) may round
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    BoxInfluence b = *box;
    b.innerHalfExtentsMeters = glm::max(
        b.halfExtentsMeters - scale * (b.halfExtentsMeters - b.innerHalfExtentsMeters), 0.0);
    return b;
  }
  SphereInfluence s = std::get<SphereInfluence>(influence);
  s.innerRadiusMeters =
      std::max(0.0, s.radiusMeters - scale * (s.radiusMeters - s.innerRadiusMeters));
  return s;
}

constexpr double kVerticalAxis = 1.0 - 1e-9;  // |own z . world z|: the box's z is vertical

bool zIsVertical(const glm::dquat& worldFromBox) {
  return std::abs((worldFromBox * glm::dvec3(0.0, 0.0, 1.0)).z) >= kVerticalAxis;
}

// The box with its bottom face (world) lowered by `drop`; its top stays.
void lowerBottom(glm::dvec3& center, glm::dvec3& halfExtents, const glm::dquat& worldFromBox,
                 double drop) {
  if (!(drop > 0.0) || !zIsVertical(worldFromBox)) return;
  center.z -= 0.5 * drop;
  halfExtents.z += 0.5 * drop;
}

// The cube centred on `capture`, world axes, its half-extent the mean distance from `capture` to
// the box's six faces (of its world bounds).
BoxShape cubeAbout(const BoxShape& box, glm::dvec3 capture) {
  glm::dvec3 reach(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 e(0.0);
    e[axis] = 1.0;
    const glm::dvec3 own = glm::abs(glm::conjugate(box.worldFromBox) * e);
    reach[axis] = glm::dot(own, box.halfExtentsMeters);  // the box's world half-width there
  }
  const glm::dvec3 low = box.centerMeters - reach, high = box.centerMeters + reach;
  const glm::dvec3 near = glm::max(capture - low, 0.0), far = glm::max(high - capture, 0.0);
  const double half = std::max((near.x + near.y + near.z + far.x + far.y + far.z) / 6.0, 0.01);
  return {capture, glm::dvec3(half), glm::dquat(1, 0, 0, 0)};
}

// The box cut to a box influence's outer range along its own x and y, where both are turned
// alike; its height stays.
void clipInPlan(BoxShape& box, const InfluenceVolume& influence) {
  const auto* in = std::get_if<BoxInfluence>(&influence);
  if (!in || std::abs(glm::dot(in->worldFromBox, box.worldFromBox)) < kVerticalAxis) return;
  const glm::dquat boxFromWorld = glm::conjugate(box.worldFromBox);
  const glm::dvec3 offset = boxFromWorld * (in->centerMeters - box.centerMeters);
  for (int axis = 0; axis < 2; ++axis) {
    const double low =
        std::max(-box.halfExtentsMeters[axis], offset[axis] - in->halfExtentsMeters[axis]);
    const double high =
        std::min(box.halfExtentsMeters[axis], offset[axis] + in->halfExtentsMeters[axis]);
    if (!(high > low)) return;  // no overlap: keep the box (never the case for a probe's own)
    const double shift = 0.5 * (low + high);
    box.centerMeters += box.worldFromBox * (shift * glm::dvec3(axis == 0, axis == 1, 0));
    box.halfExtentsMeters[axis] = 0.5 * (high - low);
  }
}

RuntimeEngines enginesFor(const ProbeProxyBuild& build, const Probe& probe,
                          const EnginePresetPolicy& policy) {
  InfluenceVolume influence = scaledFade(probe.influence, policy.fadeScale);
  const double drop = std::max(kFloorClearanceMeters,
                               policy.clearTheFloor ? transitionDistanceMeters(influence) : 0.0);
  if (auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 inner = box->innerHalfExtentsMeters - box->halfExtentsMeters;
    lowerBottom(box->centerMeters, box->halfExtentsMeters, box->worldFromBox, drop);
    box->innerHalfExtentsMeters = glm::max(box->halfExtentsMeters + inner, 0.0);
  }
  const auto lowered = [&](BoxShape b) {
    if (policy.clipToInfluence) clipInPlan(b, influence);
    return withBottomLowered(b, drop);
  };
  RuntimeEngines engines;
  const auto& cs = build.candidates;
  const ProxyCandidate& kept = cs[build.kept];
  std::optional<BoxShape> keptAsBox = keptBox(kept.shape);
  if (keptAsBox && !holdsVolume(*keptAsBox)) keptAsBox.reset();

  if (keptAsBox && isAabb(*keptAsBox)) {
    engines.unity = unityReflectionProbe(lowered(*keptAsBox), probe.captureMeters, influence);
    engines.unity->source = sourceOf(kept, true);
  } else if (const auto i = bestCandidate(cs, isAabb)) {
    engines.unity = unityReflectionProbe(lowered(std::get<BoxShape>(cs[*i].shape)),
                                         probe.captureMeters, influence);
    engines.unity->source = sourceOf(cs[*i], *i == build.kept);
  }

  std::optional<BoxShape> box;
  EngineSource source;
  if (keptAsBox) {
    box = keptAsBox;
    source = sourceOf(kept, true);
  } else if (const auto i = bestCandidate(cs, isBox)) {
    box = std::get<BoxShape>(cs[*i].shape);
    source = sourceOf(cs[*i], *i == build.kept);
  }
  if (box) {
    box = lowered(*box);
    engines.unrealBox = unrealBoxReflectionCapture(*box, probe.captureMeters, influence);
    engines.unrealBox->source = source;
    engines.godot = godotReflectionProbe(*box, probe.captureMeters, influence);
    engines.godot->source = source;
    engines.godot4 = engines.godot;
    engines.bevy =
        bevyLightProbe(policy.cubeAboutCapture ? cubeAbout(*box, probe.captureMeters) : *box,
                       probe.captureMeters, influence);
    engines.bevy->source = source;
    engines.unityHdrp = unityHdrpReflectionProbe(*box, probe.captureMeters, influence);
    engines.unityHdrp->source = source;
    engines.eevee =
        policy.eeveeAtBoxCentre
            ? eeveeReflectionCubemapAtBoxCentre(*box, transitionDistanceMeters(influence))
            : eeveeReflectionCubemap(*box, probe.captureMeters, influence, policy.influenceInside);
    engines.eevee->source = source;
  }
  if (const auto i = bestCandidate(cs, isTrueSphere)) {
    engines.unrealSphere =
        unrealSphereReflectionCapture(std::get<SphereShape>(cs[*i].shape), probe.captureMeters);
    engines.unrealSphere->source = sourceOf(cs[*i], *i == build.kept);
  }
  return engines;
}

// Enlighten measures distance to a box in the box's own frame; the probe's region is its
// influence's outer range, and a sphere's is its bounding cube.
EnlightenBlend enlightenFor(const InfluenceVolume& influence) {
  EnlightenBlend blend;
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    blend.box = {box->centerMeters, box->halfExtentsMeters, box->worldFromBox};
  } else {
    const auto& sphere = std::get<SphereInfluence>(influence);
    blend.box = {sphere.centerMeters, glm::dvec3(sphere.radiusMeters), glm::dquat(1, 0, 0, 0)};
  }
  return blend;
}

void describeShape(const ProxyShape& shape, RuntimeProbe& out) {
  if (const auto* k = std::get_if<CheapKShape>(&shape)) {
    out.kPerMeter = k->kPerMeter;
  } else if (const auto* box = std::get_if<BoxShape>(&shape)) {
    out.box = *box;
    out.worldToUnit = toUnitTransform(box->centerMeters, box->halfExtentsMeters, box->worldFromBox);
    out.convex = convexFromBox(*box);
  } else if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    out.sphere = *sphere;
    out.worldToUnit =
        toUnitTransform(sphere->centerMeters, sphere->radiiMeters, sphere->worldFromSphere);
    out.convex = icosphereMesh(sphere->centerMeters, sphere->radiiMeters, sphere->worldFromSphere);
    out.meshIsDisplayOnly = true;
  } else if (const auto* convex = std::get_if<ConvexProxy>(&shape)) {
    out.convex = *convex;
  }
}

}  // namespace

BoxShape withBottomLowered(BoxShape box, double drop) {
  lowerBottom(box.centerMeters, box.halfExtentsMeters, box.worldFromBox, drop);
  return box;
}

RuntimeExport makeRuntimeExport(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                                const EnginePresetPolicy& policy) {
  if (!(policy.fadeScale >= 0.0 && policy.fadeScale <= 4.0))
    throw std::invalid_argument("runtime export: fade scale outside [0, 4]");
  if (!(scene.metersPerUnit > 0.0) || !std::isfinite(scene.metersPerUnit)) {
    throw std::invalid_argument("runtime export: meters_per_unit must be a positive number");
  }
  RuntimeExport runtime;
  runtime.fileUp = scene.fileUp;
  runtime.metersPerUnit = scene.metersPerUnit;
  std::set<std::string> seen;
  for (const ProbeProxyBuild& build : builds) {
    const auto probe = std::find_if(scene.probes.begin(), scene.probes.end(),
                                    [&](const Probe& p) { return p.name == build.probe; });
    if (probe == scene.probes.end()) failShape(build.probe, "not a probe of the scene");
    if (!seen.insert(build.probe).second) failShape(build.probe, "built twice");
    if (build.kept >= build.candidates.size()) failShape(build.probe, "kept index out of range");
    for (const ProxyCandidate& c : build.candidates)
      checkShape(build.probe + "' candidate '" + candidateName(c), c.shape);

    const ProxyCandidate& kept = build.candidates[build.kept];
    RuntimeProbe out;
    out.name = probe->name;
    out.captureMeters = probe->captureMeters;
    out.method = methodOf(kept.shape);
    out.candidate = candidateName(kept);
    describeShape(kept.shape, out);
    out.planesCount = planeCount(kept.shape);
    out.influence = probe->influence;
    out.enlighten = enlightenFor(probe->influence);
    out.error = kept.error;
    out.engines = enginesFor(build, *probe, policy);
    runtime.probes.push_back(std::move(out));
  }
  return runtime;
}

LevelMesh runtimeExportMesh(const RuntimeExport& runtime) {
  LevelMesh mesh;
  for (const RuntimeProbe& probe : runtime.probes) {
    if (probe.convex.triangles.empty()) continue;
    LevelMesh part;
    for (const glm::dvec3& v : probe.convex.verticesMeters) part.positionsMeters.emplace_back(v);
    part.triangles = probe.convex.triangles;
    part.parts.push_back(
        {probe.name + "_proxy", {}, 0, static_cast<std::uint32_t>(probe.convex.triangles.size())});
    appendLevelMesh(mesh, part);
  }
  return mesh;
}

}  // namespace probeproxy
