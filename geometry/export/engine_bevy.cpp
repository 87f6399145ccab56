#include "geometry/export/engine_probes.h"

#include "core/scene/file_frame.h"

#include <glm/geometric.hpp>

namespace probeproxy {

namespace {
constexpr double kSamePointMeters = 1e-6;  // capture point "at" the box centre
}  // namespace

BevyLightProbe bevyLightProbe(const BoxShape& box, glm::dvec3 captureMeters) {
  const FileFrame gltf = gltfFrame();  // Bevy's axes are glTF's, metres
  BevyLightProbe probe;
  probe.translation = filePointFromWorld(gltf, box.centerMeters);
  probe.rotation = fileRotationFromWorld(gltf, box.worldFromBox);  // exact
  probe.scale = 2.0 * fileHalfExtentsFromWorld(gltf, box.halfExtentsMeters);
  probe.exact = glm::distance(captureMeters, box.centerMeters) <= kSamePointMeters;
  return probe;
}

}  // namespace probeproxy
