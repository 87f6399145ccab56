#include "geometry/export/engine_probes.h"

#include "core/scene/file_frame.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace probeproxy {

namespace {
constexpr double kGodotOffsetMarginMeters = 0.01;  // ReflectionProbe::set_origin_offset's clamp
}  // namespace

GodotReflectionProbe godotReflectionProbe(const BoxShape& box, glm::dvec3 captureMeters,
                                          const InfluenceVolume& influence) {
  const FileFrame gltf = gltfFrame();  // Godot's axes are glTF's, metres
  GodotReflectionProbe probe;
  probe.origin = filePointFromWorld(gltf, box.centerMeters);
  probe.rotation = fileRotationFromWorld(gltf, box.worldFromBox);  // exact
  probe.size = 2.0 * fileHalfExtentsFromWorld(gltf, box.halfExtentsMeters);
  probe.originOffset = glm::conjugate(probe.rotation) *
                       fileDirectionFromWorld(gltf, captureMeters - box.centerMeters);
  const glm::dvec3 room = probe.size / 2.0 - kGodotOffsetMarginMeters;
  probe.exact = glm::all(glm::lessThanEqual(glm::abs(probe.originOffset), room));
  probe.blendDistance = transitionDistanceMeters(influence);
  const glm::dvec3 farthestCorner = glm::abs(probe.originOffset) + probe.size / 2.0;
  probe.maxDistance = std::ceil(glm::length(farthestCorner) * 1000.0) / 1000.0;
  return probe;
}

}  // namespace probeproxy
