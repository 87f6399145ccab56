#include "geometry/engines/engine_model.h"

#include "core/parallax/reference_lookup.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/export/runtime_probe_shape.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace probeproxy {

namespace {

// The far slab crossing of the ray (x, r) in the box's own frame: the shaders' box projection,
// whichever side of the box x is on (then it may lie behind x). fmax drops the NaN of 0 / 0 (a
// ray in a face's plane).
std::optional<double> boxSlabExit(const BoxShape& box, glm::dvec3 x, glm::dvec3 r) {
  const glm::dquat boxFromWorld = glm::conjugate(box.worldFromBox);
  const glm::dvec3 p = boxFromWorld * (x - box.centerMeters);
  const glm::dvec3 d = boxFromWorld * r;
  double t = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double h = box.halfExtentsMeters[axis];
    t = std::fmin(t, std::fmax((h - p[axis]) / d[axis], (-h - p[axis]) / d[axis]));
  }
  // Behind x when x is outside the box: the shaders use it as it comes, and so do we.
  if (!std::isfinite(t)) return std::nullopt;
  return t;
}

}  // namespace

EngineModel genericModel(std::span<const glm::dvec3> captures,
                         std::span<const InfluenceVolume> influences,
                         std::span<const ProxyShape> shapes, const BlendOptions& options) {
  if (captures.size() != influences.size() || captures.size() != shapes.size())
    throw std::invalid_argument("genericModel: captures, influences and shapes differ in count");
  EngineModel model;
  model.engine = Engine::Generic;
  for (std::size_t i = 0; i < captures.size(); ++i) {
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = captures[i];
    p.projection = shapes[i];
    p.method = Projection::Reference;
    p.lookupOriginMeters = captures[i];
    model.probes.push_back(std::move(p));
  }
  std::vector<InfluenceVolume> volumes(influences.begin(), influences.end());
  model.blend = [volumes = std::move(volumes), options](glm::dvec3 x, glm::dvec3) {
    EngineBlend blend;
    for (const ProbeWeight& w :
         blendWeights(volumes, x + glm::dvec3(0.0, 0.0, kBlendLiftMeters), options))
      blend.weights.push_back({w.probe, w.weight});
    blend.fallbackWeight = blend.weights.empty() ? 1.0 : 0.0;
    return blend;
  };
  return model;
}

EngineModel engineModel(Engine engine, const RuntimeExport& presets, const BlendOptions& blend) {
  switch (engine) {
    case Engine::Generic: {
      std::vector<glm::dvec3> captures;
      std::vector<InfluenceVolume> influences;
      std::vector<ProxyShape> shapes;
      for (const RuntimeProbe& p : presets.probes) {
        captures.push_back(p.captureMeters);
        influences.push_back(p.influence);
        shapes.push_back(runtimeProbeShape(p, kProxiesJsonName));
      }
      return genericModel(captures, influences, shapes, blend);
    }
    case Engine::Unity:
      return unityModel(presets);
    case Engine::UnityHdrp:
      return unityHdrpModel(presets);
    case Engine::Unreal:
      return unrealModel(presets);
    case Engine::Godot3:
      return godot3Model(presets);
    case Engine::Godot4:
      return godot4Model(presets);
    case Engine::Bevy:
      return bevyModel(presets);
    case Engine::Eevee:
      return eeveeModel(presets);
  }
  throw std::invalid_argument("engineModel: unknown engine");
}

std::optional<glm::dvec3> engineLookup(const EngineProbe& probe, glm::dvec3 x, glm::dvec3 r) {
  if (probe.method == Projection::Reference)
    return referenceLookup(probe.projection, probe.captureMeters, x, r);
  if (std::holds_alternative<InfiniteShape>(probe.projection)) return probe.lookupFromWorld * r;
  std::optional<double> t;
  if (const auto* box = std::get_if<BoxShape>(&probe.projection))
    t = boxSlabExit(*box, x, r);
  else
    t = exitDistance(probe.projection, x, r);
  if (!t) return std::nullopt;
  const glm::dvec3 d = probe.lookupFromWorld * (x + *t * r - probe.lookupOriginMeters);
  if (glm::dot(d, d) == 0.0) return std::nullopt;
  return d;
}

bool capturedAt(const EngineProbe& probe, glm::dvec3 p) {
  if (!probe.depth) return true;
  const glm::dvec3 local = glm::conjugate(probe.depth->worldFromFaces) * (p - probe.captureMeters);
  const glm::dvec3 a = glm::abs(local);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const double far =
      local[axis] >= 0.0 ? probe.depth->positiveMeters[axis] : probe.depth->negativeMeters[axis];
  return a[axis] < far;
}

double engineLookupErrorDeg(const EngineProbe& probe, const ReflectionSample& s) {
  const std::optional<glm::dvec3> d = engineLookup(probe, s.xMeters, s.reflected);
  if (!d) return std::numeric_limits<double>::quiet_NaN();
  const glm::dvec3 ideal = s.hitsSky ? s.reflected : s.trueHitMeters - probe.captureMeters;
  return angleBetweenDeg(*d, ideal);
}

}  // namespace probeproxy
