#include "geometry/engines/preset_boxes.h"

#include "core/scene/file_frame.h"

#include <glm/common.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace probeproxy {

namespace {
constexpr double kGodotOffsetMarginMeters = 0.01;  // ReflectionProbe::set_origin_offset's clamp
}  // namespace

PresetBox unityPresetBox(const UnityReflectionProbe& preset) {
  const FileFrame unity = unityFrame();
  PresetBox out;
  out.captureMeters = worldPointFromFile(unity, preset.position);
  out.box.centerMeters = out.captureMeters + worldPointFromFile(unity, preset.center);
  out.box.halfExtentsMeters = worldHalfExtentsFromFile(unity, preset.size / 2.0);
  out.fadeMeters = preset.blendDistance;
  return out;
}

HdrpHeld unityHdrpHeld(const UnityHdrpReflectionProbe& preset) {
  const FileFrame unity = unityFrame();
  HdrpHeld out;
  out.sphere = preset.sphere;
  out.influenceBox.centerMeters = worldPointFromFile(unity, preset.position);
  out.influenceBox.worldFromBox = worldRotationFromFile(unity, preset.rotation);
  out.influenceBox.halfExtentsMeters = worldHalfExtentsFromFile(unity, preset.boxSize / 2.0);
  // A box's own axes turn with the frame: Unity's own axis i is the world's own axis
  // axis[i], reversed where sign[i] < 0, and then its + face is the world's - face.
  for (int i = 0; i < 3; ++i) {
    const int w = unity.axis[static_cast<std::size_t>(i)];
    const bool kept = unity.sign[static_cast<std::size_t>(i)] > 0.0;
    out.blendPositive[w] = worldLengthFromFile(
        unity, kept ? preset.blendDistancePositive[i] : preset.blendDistanceNegative[i]);
    out.blendNegative[w] = worldLengthFromFile(
        unity, kept ? preset.blendDistanceNegative[i] : preset.blendDistancePositive[i]);
  }
  out.sphereRadiusMeters = worldLengthFromFile(unity, preset.sphereRadius);
  out.sphereBlendMeters = worldLengthFromFile(unity, preset.blendDistancePositive.x);
  out.proxy.centerMeters = worldPointFromFile(unity, preset.proxyPosition);
  out.proxy.worldFromBox = worldRotationFromFile(unity, preset.proxyRotation);
  out.proxy.halfExtentsMeters = worldHalfExtentsFromFile(unity, preset.proxySize / 2.0);
  out.captureMeters = worldPointFromFile(unity, preset.capturePosition);
  return out;
}

PresetBox unrealPresetBox(const UnrealBoxReflectionCapture& preset) {
  const FileFrame unreal = unrealFrame();
  PresetBox out;
  out.box.centerMeters = worldPointFromFile(unreal, preset.location);
  out.box.worldFromBox = worldRotationFromFile(unreal, preset.rotation);
  out.box.halfExtentsMeters = worldHalfExtentsFromFile(unreal, preset.scale3D);
  out.captureMeters = out.box.centerMeters + worldPointFromFile(unreal, preset.captureOffset);
  out.fadeMeters = worldLengthFromFile(unreal, preset.boxTransitionDistance);
  return out;
}

PresetBox godotPresetBox(const GodotReflectionProbe& preset) {
  const FileFrame gltf = gltfFrame();  // Godot's axes are glTF's, metres
  const glm::dvec3 extents = preset.size / 2.0;
  const glm::dvec3 room = glm::max(extents - kGodotOffsetMarginMeters, glm::dvec3(0.0));
  const glm::dvec3 offset = glm::clamp(preset.originOffset, -room, room);
  PresetBox out;
  out.box.centerMeters = worldPointFromFile(gltf, preset.origin);
  out.box.worldFromBox = worldRotationFromFile(gltf, preset.rotation);
  out.box.halfExtentsMeters = worldHalfExtentsFromFile(gltf, extents);
  out.captureMeters = worldPointFromFile(gltf, preset.origin + preset.rotation * offset);
  out.fadeMeters = preset.blendDistance;
  return out;
}

PresetBox bevyPresetBox(const BevyLightProbe& preset) {
  const FileFrame gltf = gltfFrame();  // Bevy's axes are glTF's, metres
  PresetBox out;
  out.box.centerMeters = worldPointFromFile(gltf, preset.translation);
  out.box.worldFromBox = worldRotationFromFile(gltf, preset.rotation);
  out.box.halfExtentsMeters = worldHalfExtentsFromFile(gltf, preset.scale / 2.0);
  out.captureMeters = out.box.centerMeters;
  const glm::dvec3 fade = preset.falloff * preset.scale / 2.0;
  out.fadeMeters = std::min({fade.x, fade.y, fade.z});
  return out;
}

}  // namespace probeproxy
