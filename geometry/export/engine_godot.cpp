#include "geometry/export/engine_probes.h"

#include "geometry/export/export_frame.h"

#include <glm/common.hpp>
#include <glm/gtc/quaternion.hpp>

namespace probeproxy {

namespace {
const ExportFrame kGltfFrame{UpAxis::Y, 1.0};      // glTF's axes, metres
constexpr double kGodotOffsetMarginMeters = 0.01;  // ReflectionProbe::set_origin_offset's clamp
}  // namespace

GodotReflectionProbe godotReflectionProbe(const BoxShape& box, glm::dvec3 captureMeters) {
  // Godot's axes are glTF's: the Y-up file frame of the scene file, in metres.
  GodotReflectionProbe probe;
  probe.origin = yUpFromZUp(box.centerMeters);
  probe.rotation = fileRotationFromWorld(kGltfFrame, box.worldFromBox);  // exact
  const glm::dvec3 h = box.halfExtentsMeters;  // the box's own axes turn with the frame
  probe.size = 2.0 * glm::dvec3(h.x, h.z, h.y);
  probe.originOffset =
      glm::conjugate(probe.rotation) * yUpFromZUp(captureMeters - box.centerMeters);
  const glm::dvec3 room = probe.size / 2.0 - kGodotOffsetMarginMeters;
  probe.exact = glm::all(glm::lessThanEqual(glm::abs(probe.originOffset), room));
  return probe;
}

}  // namespace probeproxy
