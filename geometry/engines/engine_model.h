#pragma once
// What a renderer does with the probes it was given, as plain data and one function: the
// probes as the engine holds them (capture point, the shape a reflection is projected on, how
// the cubemap is looked up) and, for a shaded point, which of them reach it with what weight
// and how much is left to the sky / ambient fallback. World frame (Z up), metres.
//
// The level-wide error under a model (geometry/survey/blended_error.h) is the weight-averaged
// angle between each probe's lookup and the true hit, as for the generic model; the fallback's
// share is the part of the reflection no probe provides (counted as uncovered, not as error).

#include "core/blend/blend_weights.h"
#include "core/proxy/proxy_shape.h"
#include "core/scene/influence_volume.h"
#include "geometry/engines/engine.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/export/runtime_export.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace probeproxy {

// How the engine intersects a reflection ray with its projection shape.
enum class Projection {
  Reference,  // probeproxy's own lookup (core/parallax/reference_lookup.h): a shading point
              // outside the shape is a miss
  BoxSlab,    // the engines' box projection: t = min over axes of the far slab crossing, in the
              // box's own frame (UnityStandardUtils.cginc BoxProjectedCubemapDirection, Godot's
              // reflection_process, Unreal's GetLookupVectorForBoxCapture, HDRP's
              // IntersectBoxProxy, EEVEE's line_unit_box_intersect_dist): from outside the box
              // too, and t < 0 as it comes, as the shaders do
};

// How deep each face of a cubemap was rendered: a face sees along its axis (in `worldFromFaces`'
// frame, from the capture point) only up to its far plane. Level points past it are not in the
// cubemap; its texels there hold the probe's clear colour, no level point.
struct CaptureDepth {
  glm::dquat worldFromFaces{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 positiveMeters{0.0};  // far plane of the +x, +y, +z faces
  glm::dvec3 negativeMeters{0.0};  // of the -x, -y, -z faces
};

struct EngineProbe {
  int sceneProbe = 0;             // the probe's index in the scene (and in the export)
  glm::dvec3 captureMeters{0.0};  // where the cubemap was captured: its texels are seen from here
  ProxyShape projection;          // what the reflection ray is intersected with; InfiniteShape:
                                  // no parallax correction (the lookup is r)
  Projection method = Projection::BoxSlab;
  // The engine looks the cubemap up with lookupFromWorld * (P - lookupOriginMeters), P where
  // the ray leaves `projection`. Most engines: the identity and the capture point. Bevy looks
  // up in the probe's own scaled space from the box centre.
  glm::dvec3 lookupOriginMeters{0.0};
  glm::dmat3 lookupFromWorld{1.0};
  std::optional<CaptureDepth> depth;  // none: the cubemap holds the whole level
};

// Whether the probe's cubemap holds the level point p: the face p is seen through (the largest
// axis of p - capture, in the faces' frame) reaches past it. A point on the far plane is
// clipped: Godot 3 drops a wall lying there (a box fitted to its room, max_distance 0).
bool capturedAt(const EngineProbe& probe, glm::dvec3 pMeters);

struct EngineWeight {
  int probe = 0;        // index into EngineModel::probes
  double weight = 0.0;  // in (0, 1]
};

struct EngineBlend {
  std::vector<EngineWeight> weights;  // in the engine's order; zero weights left out
  double fallbackWeight = 1.0;        // the sky / ambient's share: 1 - sum(weights), >= 0
};

struct ProbeFade {
  int probe = 0;      // index into EngineModel::probes
  double fade = 0.0;  // the probe's own weight at the point, in [0, 1]
};

struct EngineModel {
  Engine engine = Engine::Generic;
  std::vector<EngineProbe> probes;
  // The blend at a shaded point x seen from a camera at `eye` (Godot 4 orders probes by their
  // depth from the camera). Deterministic; safe to call from many threads.
  std::function<EngineBlend(glm::dvec3 xMeters, glm::dvec3 eyeMeters)> blend;
  // The same blend in its two steps, so that some of the probes can be blended without a new
  // model (an engine's layout weighing which probes to keep): each probe's own fade at x, the
  // positive ones in the order the engine visits them, and how the engine composes such a
  // list (its probe numbers are only carried through to the weights: any labels do);
  // blend(x, eye) is compose(fades(x, eye)). Empty for the generic model, whose weights are
  // normalized over the most influential volumes and so not composed one by one.
  std::function<std::vector<ProbeFade>(glm::dvec3 xMeters, glm::dvec3 eyeMeters)> fades;
  std::function<EngineBlend(std::span<const ProbeFade> ordered)> compose;
  // A fade at or over which `compose` gives the probes after it nothing (front to back and up
  // to the largest fade: 1; fill to one: where it stops); infinity where every probe counts
  // however full the ones before it are (an average). A search over which probes to keep need
  // not weigh what lies behind such a probe.
  double fullFade = std::numeric_limits<double>::infinity();
  // `compose` is normalizedFades (Godot 3): each probe's weight its fade over the sum of the
  // fades. A search may then keep a sample's sums and weigh one probe more or less in one step.
  bool averagesFades = false;
  // The most probes one shaded point gets, the first in the engine's order (0: no limit): Godot
  // 3 gives an object the first 8 probes paired with it. `compose` takes the first that many of
  // the list it is given.
  std::size_t mostProbes = 0;
};

// Sets the model's fades and composition (full at `fullFade`), and its blend as the two in turn.
template <typename Fades, typename Compose>
void setBlend(EngineModel& model, Fades fades, Compose compose,
              double fullFade = std::numeric_limits<double>::infinity()) {
  model.fades = std::move(fades);
  model.compose = std::move(compose);
  model.fullFade = fullFade;
  model.blend = [fades = model.fades, compose = model.compose](glm::dvec3 x, glm::dvec3 eye) {
    return compose(fades(x, eye));
  };
}

// The generic model over given shapes: Lagarde's or Enlighten's weights (core/blend/
// blend_weights.h) taken kBlendLiftMeters above the floor point, each probe looked up through
// its own proxy from its capture point. The three spans are in scene order, of equal length.
EngineModel genericModel(std::span<const glm::dvec3> capturesMeters,
                         std::span<const InfluenceVolume> influences,
                         std::span<const ProxyShape> shapes, const BlendOptions& blend);

// The model of `engine` over an export's presets: what a studio imports. A probe without a
// preset for that engine (no box candidate was built) is not in the engine at all. Generic
// takes each probe's kept proxy and `blend`.
EngineModel engineModel(Engine engine, const RuntimeExport& presets, const BlendOptions& blend);

// One file per engine (geometry/engines/<name>_model.cpp).
EngineModel unityModel(const RuntimeExport& presets);
EngineModel unityHdrpModel(const RuntimeExport& presets);
EngineModel unrealModel(const RuntimeExport& presets);
EngineModel godot3Model(const RuntimeExport& presets);
EngineModel godot4Model(const RuntimeExport& presets);
EngineModel bevyModel(const RuntimeExport& presets);
EngineModel eeveeModel(const RuntimeExport& presets);

// The engine's lookup direction for the ray (x, r) (r unit); none for a miss.
std::optional<glm::dvec3> engineLookup(const EngineProbe& probe, glm::dvec3 xMeters, glm::dvec3 r);

// angle(lookup, H - C) in degrees, C the capture point (r when the ray reaches the sky); NaN
// for a miss. The generic model's probes give angularErrorDeg exactly.
double engineLookupErrorDeg(const EngineProbe& probe, const ReflectionSample& sample);

// Floor points sit on the influence volumes' lower boundary (a box from floor to ceiling);
// the generic model takes weights this far above the floor, as validate's floor rules do.
// Engine models take them at the shaded point itself, as their shaders do.
inline constexpr double kBlendLiftMeters = 0.05;

}  // namespace probeproxy
