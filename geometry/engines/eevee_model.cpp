// Blender 3.x EEVEE's Reflection Cubemap light probes (source/blender/draw/engines/eevee/
// eevee_lightprobes.c, EEVEE_lightprobes_cube_data_from_object(); eevee_lightcache.c,
// eevee_lightbake_gather_probes(); shaders/lightprobe_lib.glsl):
//   - the probe object's location is the capture point and the centre of both volumes; the
//     influence is the object's transform scaled by influence_distance, the parallax volume the
//     same transform scaled by parallax_distance (a uniformly scaled copy, same rotation);
//   - probe_attenuation_cube(): localpos in the influence's unit space, fac = saturate(a - a *
//     |localpos|) per axis (box: the smallest; sphere: of the length), a = 1 / falloff: 1 up to
//     1 - falloff of the way to each face, 0 on it, along Z too;
//   - fallback_cubemap(): probes in the light cache's order, each through accumulate_light(),
//     accum += min(fade, 1 - accum.a), until accum.a reaches 0.999; the world probe takes what
//     is left. The bake sorts cube probes by mat4_to_scale of their inverse influence matrix,
//     largest first: the smallest influence first;
//   - probe_evaluate_cube(): the ray from the shading point is intersected with the parallax
//     box (line_unit_box_intersect_dist) or sphere, and the lookup is hit - probe position.
//
// The preset a studio makes from the export, since EEVEE centres both volumes on the capture
// point: influence box in the influence volume's axes, each half-extent the capture point's
// larger distance to that axis' faces (so the scene's whole outer range is covered); falloff
// = the scene's fade (engine_probes.h transitionDistanceMeters) over the shortest half-extent;
// parallax box = the influence box scaled by the one factor that fits it best, in least
// squares, to the capture point's distances to the faces of the box the other engines get.

#include "geometry/engines/blend_composition.h"
#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace probeproxy {

namespace {

constexpr double kSmallestFalloff = 1e-8;  // EEVEE_lightprobes_cube_data_from_object
constexpr double kFull = 0.999;            // fallback_cubemap's loop and world test

struct EeveeProbe {
  glm::dvec3 positionMeters{0.0};
  glm::dquat worldFromProbe{1, 0, 0, 0};
  glm::dvec3 influenceHalfExtentsMeters{1.0};  // sphere: all three the radius
  bool sphere = false;
  double attenuation = 1.0;  // 1 / falloff
};

// The support of a box along a unit direction, from a point: how far its farthest face is.
double reachAlong(const BoxShape& box, glm::dvec3 from, glm::dvec3 direction) {
  double reach = glm::dot(box.centerMeters - from, direction);
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 boxAxis(0.0);
    boxAxis[axis] = 1.0;
    reach +=
        box.halfExtentsMeters[axis] * std::abs(glm::dot(box.worldFromBox * boxAxis, direction));
  }
  return reach;
}

EeveeProbe eeveeProbe(const InfluenceVolume& influence, glm::dvec3 capture, double fade) {
  EeveeProbe e;
  e.positionMeters = capture;
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    e.worldFromProbe = box->worldFromBox;
    const glm::dvec3 offset = glm::conjugate(box->worldFromBox) * (capture - box->centerMeters);
    e.influenceHalfExtentsMeters = box->halfExtentsMeters + glm::abs(offset);
  } else {
    const auto& sphere = std::get<SphereInfluence>(influence);
    e.sphere = true;
    e.influenceHalfExtentsMeters =
        glm::dvec3(sphere.radiusMeters + glm::length(capture - sphere.centerMeters));
  }
  const glm::dvec3 h = e.influenceHalfExtentsMeters;
  const double falloff = std::clamp(fade / std::min({h.x, h.y, h.z}), kSmallestFalloff, 1.0);
  e.attenuation = 1.0 / falloff;
  return e;
}

// Parallax half-extents k * influence, k fitted to the capture point's mean distance to the
// proxy box's faces along each of the probe's axes.
BoxShape parallaxBox(const EeveeProbe& e, const BoxShape& proxy) {
  double numerator = 0.0, denominator = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    glm::dvec3 unit(0.0);
    unit[axis] = 1.0;
    const glm::dvec3 direction = e.worldFromProbe * unit;
    const double wanted = 0.5 * (reachAlong(proxy, e.positionMeters, direction) +
                                 reachAlong(proxy, e.positionMeters, -direction));
    numerator += e.influenceHalfExtentsMeters[axis] * wanted;
    denominator += e.influenceHalfExtentsMeters[axis] * e.influenceHalfExtentsMeters[axis];
  }
  return {e.positionMeters, (numerator / denominator) * e.influenceHalfExtentsMeters,
          e.worldFromProbe};
}

double attenuation(const EeveeProbe& e, glm::dvec3 x) {
  const glm::dvec3 local =
      glm::conjugate(e.worldFromProbe) * (x - e.positionMeters) / e.influenceHalfExtentsMeters;
  if (e.sphere) return std::clamp(e.attenuation - e.attenuation * glm::length(local), 0.0, 1.0);
  const glm::dvec3 axes = glm::clamp(e.attenuation - e.attenuation * glm::abs(local), 0.0, 1.0);
  return std::min({axes.x, axes.y, axes.z});
}

// mat4_to_scale of the inverse influence matrix: |diag(1 / h) R^T (1, 1, 1) / sqrt(3)|.
double inverseScale(const EeveeProbe& e) {
  const glm::dvec3 u = glm::conjugate(e.worldFromProbe) * glm::dvec3(1.0 / std::sqrt(3.0));
  return glm::length(u / e.influenceHalfExtentsMeters);
}

}  // namespace

EngineModel eeveeModel(const RuntimeExport& presets) {
  EngineModel model;
  model.engine = Engine::Eevee;
  std::vector<EeveeProbe> held;
  for (std::size_t i = 0; i < presets.probes.size(); ++i) {
    const RuntimeProbe& probe = presets.probes[i];
    if (!probe.engines.unrealBox) continue;
    const PresetBox proxy = unrealPresetBox(*probe.engines.unrealBox);
    const EeveeProbe e =
        eeveeProbe(probe.influence, probe.captureMeters, transitionDistanceMeters(probe.influence));
    EngineProbe p;
    p.sceneProbe = static_cast<int>(i);
    p.captureMeters = e.positionMeters;
    p.lookupOriginMeters = e.positionMeters;
    p.projection = parallaxBox(e, proxy.box);
    model.probes.push_back(std::move(p));
    held.push_back(e);
  }
  std::vector<int> order(held.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return inverseScale(held[static_cast<std::size_t>(a)]) >
           inverseScale(held[static_cast<std::size_t>(b)]);
  });
  model.blend = [held = std::move(held), order = std::move(order)](glm::dvec3 x, glm::dvec3) {
    std::vector<ProbeFade> fades;
    for (const int i : order) {
      const double fade = attenuation(held[static_cast<std::size_t>(i)], x);
      if (fade > 0.0) fades.push_back({i, fade});
    }
    return fillToOne(fades, kFull);
  };
  return model;
}

}  // namespace probeproxy
