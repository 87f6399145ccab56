#pragma once
// What each engine holds once it has read an exported preset (geometry/export/engine_probes.h),
// back in the world frame: the engine's own formula for its box and capture point, the one
// tests/e2e/engine_presets_test.cpp applies to the JSON. The engine models start from these,
// so what they measure is what the export gives the engine.

#include "core/proxy/proxy_shape.h"
#include "geometry/export/engine_probes.h"

#include <glm/vec3.hpp>

namespace probeproxy {

struct PresetBox {
  BoxShape box;                   // world frame, metres
  glm::dvec3 captureMeters{0.0};  // where the engine takes the cubemap to be captured
  double fadeMeters = 0.0;        // the preset's one fade distance (0 where it has none)
};

// Unity: box = [position + center -+ size / 2], axis-aligned; the capture point is position;
// fade = blendDistance (outside the box: Unity grows the box by it).
PresetBox unityPresetBox(const UnityReflectionProbe& preset);

// Unity HDRP: the influence (world frame; a box's blend distances per face of its own axes,
// inward), the proxy box and the capture position.
struct HdrpHeld {
  bool sphere = false;
  BoxShape influenceBox;          // box: centre, half-extents, rotation
  glm::dvec3 blendPositive{0.0};  // per own axis, the + face's blend distance, metres
  glm::dvec3 blendNegative{0.0};
  double sphereRadiusMeters = 0.0;  // sphere: centre influenceBox.centerMeters
  double sphereBlendMeters = 0.0;
  BoxShape proxy;
  glm::dvec3 captureMeters{0.0};
};
HdrpHeld unityHdrpHeld(const UnityHdrpReflectionProbe& preset);

// Unreal: corners = location + rotation * (+-scale_3d) (cm); capture = location + capture_offset;
// fade = box_transition_distance.
PresetBox unrealPresetBox(const UnrealBoxReflectionCapture& preset);

// Godot: corners = origin + basis * (+-size / 2); capture = origin + basis * origin_offset
// after ReflectionProbe::set_origin_offset's clamp (|offset| <= extents - 0.01 per axis, in the
// node's frame: the capture point Godot really renders from); fade = blend_distance.
PresetBox godotPresetBox(const GodotReflectionProbe& preset);

// Bevy: corners = translation + rotation * (+-scale / 2); Bevy captures at the translation
// (the cube's centre); fade: the smallest of falloff * scale / 2.
PresetBox bevyPresetBox(const BevyLightProbe& preset);

}  // namespace probeproxy
