// Unreal Engine's reflection captures, per pixel (deferred: ReflectionEnvironmentPixelShader;
// forward: the same GatherRadiance loop over the culled captures). Engine/Shaders/Private/
// ReflectionEnvironmentComposite.ush and ReflectionEnvironmentShared.ush, as docs/engines.md
// cites them (Epic's source is not public; the shader files ship with every engine install):
//   - captures are visited smallest first (the renderer sorts them by influence radius:
//     FReflectionCaptureSortData compares PositionAndRadius.W) and composited front to back:
//     ImageBasedReflections.rgb += Sample * DistanceAlpha * ImageBasedReflections.a;
//     ImageBasedReflections.a *= 1 - DistanceAlpha; what alpha is left goes to the sky light;
//   - a box capture's DistanceAlpha = 1 - smoothstep(0, 0.7 T, distance from the point to the
//     box shrunk by T / 2), T = BoxTransitionDistance: 1 from T / 2 inside each face, about 0.21
//     on the face, 0 at 0.2 T outside it; the lookup intersects the unit box under the actor's
//     transform (the whole box) and looks up hit - (location + CaptureOffset);
//   - a sphere capture's DistanceAlpha = 1 - smoothstep(0.6, 1, |x - location| / radius), the
//     reflection projected on the sphere of InfluenceRadius about the actor.
// A probe gets its box capture; a sphere capture only where the export has no box for it.
// The box capture's radius, for the order: |half-extents + T| (its influence bounding radius).

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include "core/scene/file_frame.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace probeproxy {

namespace {

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

struct Capture {
  PresetBox box;       // for a box capture
  SphereShape sphere;  // for a sphere capture
  bool isBox = true;
  double radiusMeters = 0.0;  // the sort key
};

double distanceAlpha(const Capture& c, glm::dvec3 x) {
  if (!c.isBox) {
    const double r = glm::length(x - c.sphere.centerMeters) / c.sphere.radiiMeters.x;
    return r < 1.0 ? 1.0 - smoothstep(0.6, 1.0, r) : 0.0;
  }
  const BoxShape& box = c.box.box;
  const double t = c.box.fadeMeters;
  const glm::dvec3 p = glm::abs(glm::conjugate(box.worldFromBox) * (x - box.centerMeters));
  if (!(t > 0.0))  // no transition: a hard edge at the box
    return glm::all(glm::lessThanEqual(p, box.halfExtentsMeters)) ? 1.0 : 0.0;
  const glm::dvec3 shrunk = glm::max(box.halfExtentsMeters - 0.5 * t, glm::dvec3(0.0));
  const double distance = glm::length(glm::max(p - shrunk, glm::dvec3(0.0)));
  return 1.0 - smoothstep(0.0, 0.7 * t, distance);
}

}  // namespace

EngineModel unrealModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::Unreal;
  std::vector<Capture> captures;
  const FileFrame unreal = unrealFrame();
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const RuntimeEngines& engines = presets.probes[i].engines;
    Capture c;
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    if (engines.unrealBox) {
      c.box = unrealPresetBox(*engines.unrealBox);
      c.radiusMeters = glm::length(c.box.box.halfExtentsMeters + c.box.fadeMeters);
      p.captureMeters = c.box.captureMeters;
      p.projection = c.box.box;
    } else if (engines.unrealSphere) {
      c.isBox = false;
      c.sphere.centerMeters = worldPointFromFile(unreal, engines.unrealSphere->location);
      c.sphere.radiiMeters =
          glm::dvec3(worldLengthFromFile(unreal, engines.unrealSphere->influenceRadius));
      c.radiusMeters = c.sphere.radiiMeters.x;
      p.captureMeters =
          c.sphere.centerMeters + worldPointFromFile(unreal, engines.unrealSphere->captureOffset);
      p.projection = c.sphere;
    } else {
      continue;
    }
    p.lookupOriginMeters = p.captureMeters;
    model.probes.push_back(std::move(p));
    captures.push_back(c);
  }
  std::vector<int> order = orderedBy(
      captures.size(), [&](int i) { return captures[static_cast<std::size_t>(i)].radiusMeters; });
  setBlend(
      model,
      [captures = std::move(captures), order = std::move(order)](glm::dvec3 x, glm::dvec3) {
        return fadesInOrder(order, [&](std::size_t i) { return distanceAlpha(captures[i], x); });
      },
      frontToBack, 1.0);
  return model;
}

}  // namespace probeproxy
