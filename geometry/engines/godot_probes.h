#pragma once
// What Godot 3 and Godot 4 share: a ReflectionProbe's box is both where it applies and what it
// projects on (the shaders' reflection_process(): out of the box, `return`; box_project: hit
// against +-box_extents, lookup = hit - box_offset), centred on the node. Its cubemap is
// rendered from the capture point with each face's far plane on the box's face along that axis
// (servers/visual/visual_server_scene.cpp, _render_reflection_probe_step, and Godot 4's
// RendererSceneCull: max_distance = MAX(max_distance, |extents - origin_offset| along the
// face's normal)): with max_distance 0 nothing on or past the box's faces is in the cubemap.

#include "geometry/engines/engine_model.h"
#include "geometry/engines/preset_boxes.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace probeproxy {

struct GodotProbes {
  std::vector<EngineProbe> probes;
  std::vector<PresetBox> boxes;  // same order
};

// Every probe with a preset for Godot 3 (godot_reflection_probe) or Godot 4
// (godot4_reflection_probe), as Godot holds it.
GodotProbes godotProbes(const RuntimeExport& presets, bool godot4);

// local_pos = the point in the node's frame; none where any |local_pos| > box_extents.
std::optional<glm::dvec3> godotLocalPosition(const BoxShape& box, glm::dvec3 xMeters);

}  // namespace probeproxy
