#include "geometry/export/engine_probes.h"

#include "geometry/export/export_frame.h"

#include <glm/geometric.hpp>

namespace probeproxy {

namespace {
const ExportFrame kGltfFrame{UpAxis::Y, 1.0};  // glTF's axes, metres
constexpr double kSamePointMeters = 1e-6;      // capture point "at" the box centre
}  // namespace

BevyLightProbe bevyLightProbe(const BoxShape& box, glm::dvec3 captureMeters) {
  BevyLightProbe probe;
  probe.translation = yUpFromZUp(box.centerMeters);
  probe.rotation = fileRotationFromWorld(kGltfFrame, box.worldFromBox);  // exact
  const glm::dvec3 h = box.halfExtentsMeters;
  probe.scale = 2.0 * glm::dvec3(h.x, h.z, h.y);
  probe.exact = glm::distance(captureMeters, box.centerMeters) <= kSamePointMeters;
  return probe;
}

}  // namespace probeproxy
