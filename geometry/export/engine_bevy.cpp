#include "geometry/export/engine_probes.h"

#include "core/scene/file_frame.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace probeproxy {

namespace {
constexpr double kSamePointMeters = 1e-6;    // capture point "at" the box centre
constexpr double kSameLength = 1e-9;         // relative: a cube, not a box
constexpr double kIdentityRotation = 1e-12;  // |w| this close to 1: not turned
}  // namespace

// Bevy, crates/bevy_pbr/src/light_probe/environment_map.wesl, compute_cubemap_sample_dir():
//   ray_origin = (light_from_world * vec4(world_ray_origin, 1.0)).xyz   // unit-cube space
//   t = nearest of (+-parallax_correction_bounds - ray_origin) / ray_direction, t >= 0
//   sample_dir = ray_origin + ray_direction * t                          // still unit-cube space
// light_from_world maps the probe's 1x1x1 cube to the Transform's box, so the sample direction
// is the hit point seen from the cube's centre, in the cube's own (scaled, turned) axes. It is
// the direction a cubemap captured at the centre holds only when the scale is the same on every
// axis and the probe is not turned (else the cubemap would have to be captured in the probe's
// turned axes, stretched by 1/scale): `exact` says all three hold.
BevyLightProbe bevyLightProbe(const BoxShape& box, glm::dvec3 captureMeters,
                              const InfluenceVolume& influence) {
  const FileFrame gltf = gltfFrame();  // Bevy's axes are glTF's, metres
  BevyLightProbe probe;
  probe.translation = filePointFromWorld(gltf, box.centerMeters);
  probe.rotation = fileRotationFromWorld(gltf, box.worldFromBox);  // exact
  probe.scale = 2.0 * fileHalfExtentsFromWorld(gltf, box.halfExtentsMeters);
  // LightProbe::falloff: per axis, the share of the half-size over which the weight fades,
  // inside the cube (bevy_light, LightProbe: "if you set the falloff to 0.5 on an axis, then
  // any fragments with positions between 0.0 units to 0.25 units on that axis will receive
  // 100% influence"): fade metres = falloff * scale / 2.
  const double fade = transitionDistanceMeters(influence);
  for (int axis = 0; axis < 3; ++axis) {
    probe.falloff[axis] = std::clamp(fade / (probe.scale[axis] / 2.0), 0.0, 1.0);
  }
  const double longest = std::max({probe.scale.x, probe.scale.y, probe.scale.z});
  const double shortest = std::min({probe.scale.x, probe.scale.y, probe.scale.z});
  const bool cube = longest - shortest <= kSameLength * longest;
  const bool unturned = std::abs(probe.rotation.w) >= 1.0 - kIdentityRotation;
  probe.captureAtCentre = glm::distance(captureMeters, box.centerMeters) <= kSamePointMeters;
  probe.exact = probe.captureAtCentre && cube && unturned;
  return probe;
}

}  // namespace probeproxy
