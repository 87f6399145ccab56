#pragma once
// Runtimes that accept only a box or a sphere, in their own parameters, units and axes.
// probeproxy's world is right-handed, Z up, metres; each engine's frame is fixed below so that
// the probe lines up with the level imported through that engine's usual glTF path. The frames
// are core/scene/file_frame.h's (gltfFrame, unityFrame, unrealFrame): one conversion for the
// scene file, proxies.json and the engines.
//
//   Unity:  left-handed, Y up, metres; world (x, y, z) -> (-x, z, -y): glTF's axes with x
//           negated, as UnityGLTF and glTFast import glTF (UnityGLTF issue #257:
//           CoordinateSpaceConversionScale = (-1, 1, 1)).
//   Unreal: left-handed, Z up, centimetres; world (x, y, z) -> (x, -y, z) * 100 (Y flipped, as
//           Unreal's FBX and glTF importers do).
//   Godot:  right-handed, Y up, metres; world (x, y, z) -> (x, z, -y): glTF's axes, which Godot
//           imports unchanged.
//   Bevy:   right-handed, Y up, metres; (x, z, -y) like Godot: glTF's axes as GltfPlugin loads
//           them by default (without `convert_coordinates`).
//
// Quaternions here are [x, y, z, w] (Unreal FQuat(X, Y, Z, W), Godot Quaternion(x, y, z, w),
// Bevy Quat::from_xyzw), unlike the scene file's [w, x, y, z].

#include "core/measures/error_figures.h"
#include "core/proxy/proxy_shape.h"
#include "core/scene/influence_volume.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace probeproxy {

// Which candidate an engine entry was made from, and the error that candidate was measured
// with (mirror_floor). It holds in the engine only where the entry says `exact`.
// `keptProxy`: the entry is the kept proxy itself (a box, or a convex that is one to within
// kBoxCornerToleranceMeters, keptBox() in kept_box.h), so its error is the kept proxy's;
// otherwise the engine cannot take the kept shape and `candidate` / `error` say what it gets
// instead and what that costs against the probe's own error.
struct EngineSource {
  std::string candidate;  // ProxyCandidate::kind
  ErrorFigures error;
  bool keptProxy = false;
};

// Each engine's entry below was checked against the engine's own shader and node code (or, for
// Unity and Unreal, whose engine source is not public, the documented shader include and the
// scripting reference); docs/engines.md has the same citations and the formulas the tests
// apply (tests/e2e/engine_presets_test.cpp).

// Unity ReflectionProbe with box projection. ScriptReference: ReflectionProbe.center "relative
// to the position of the probe", ReflectionProbe.size "in world space" (full size),
// boxProjection. The box projection itself, UnityStandardUtils.cginc
// BoxProjectedCubemapDirection(worldRefl, worldPos, cubemapCenter, boxMin, boxMax): boxMin /
// boxMax are world-space corners (no rotation anywhere) and the lookup is
// worldPos - cubemapCenter + nrdir * t, cubemapCenter being the probe's position: the capture
// point. So: world box = [position + center -+ size / 2], axis-aligned in Unity's world; only an
// `aabb` candidate is exported. The box is both the influence and the projection volume.
// blendDistance ("Distance around probe used for blending (used in deferred probes)", default
// 1): Internal-DeferredReflections.shader fades each probe *outside* its box over that distance
// and projects on the box grown by it. So the export writes the measured box shrunk by
// blendDistance on every side but the bottom: Unity projects on exactly the measured box, but
// for a bottom face blendDistance lower (a mirror floor's reflections go up and never meet it),
// and fades to 0 at its other faces, while a floor on the bottom keeps full weight.
// blendDistance = transitionDistanceMeters(influence), at least kUnityMinBlendMeters (Unity
// divides by it) and at most half the box's shortest half-extent.
// importance (ScriptReference ReflectionProbe.importance, default 1): "if object is inside both
// Important and Not Important probe, only Important probe will be used"; the export writes the
// default, `layout --engine unity` raises the probes that should win where boxes overlap.
struct UnityReflectionProbe {
  EngineSource source;
  glm::dvec3 position{0.0};    // Transform.position: the capture point, metres
  glm::dvec3 center{0.0};      // ReflectionProbe.center: box centre - position, metres
  glm::dvec3 size{0.0};        // ReflectionProbe.size: full size of the shrunk box, metres
  double blendDistance = 1.0;  // ReflectionProbe.blendDistance, metres
  bool boxProjection = true;
  int importance = 1;  // ReflectionProbe.importance: the higher drawn over the lower
};

inline constexpr double kUnityMinBlendMeters = 0.01;

// Unity HDRP Reflection Probe (HDProbe: influence volume, proxy volume and capture position
// apart; Manual "Reflection Probe", HDRP). Unity's axes (as UnityReflectionProbe), metres.
// The influence is a box (influence.boxSize, full size, and per-face blend distances
// boxBlendDistancePositive / Negative, measured inward from each face:
// VolumeProjection.hlsl InfluenceBoxWeight) or a sphere (sphereRadius, sphereBlendDistance),
// centred on the probe's Transform; the proxy a ReflectionProxyVolume box with its own
// transform; the cubemap is captured at capturePosition (world). Made from the scene's
// influence volume (blend on each face = outer - inner half-extent; Unity's x is the world's
// -x, so the positive and negative faces of x swap) and the box the other box engines get.
struct UnityHdrpReflectionProbe {
  EngineSource source;
  glm::dvec3 position{0.0};               // Transform.position: the influence's centre
  glm::dquat rotation{1, 0, 0, 0};        // Transform.rotation, Unity axes
  bool sphere = false;                    // influence shape: box, or sphere
  glm::dvec3 boxSize{0.0};                // influence.boxSize, full size (box)
  glm::dvec3 blendDistancePositive{0.0};  // per face, inward (box); sphere: x is the blend
  glm::dvec3 blendDistanceNegative{0.0};
  double sphereRadius = 0.0;        // influence.sphereRadius (sphere)
  glm::dvec3 capturePosition{0.0};  // where the cubemap is captured, Unity world
  glm::dvec3 proxyPosition{0.0};    // ReflectionProxyVolume's Transform.position: box centre
  glm::dquat proxyRotation{1, 0, 0, 0};
  glm::dvec3 proxySize{0.0};  // ReflectionProxyVolume box size, full
};

// Unreal BoxReflectionCapture (UBoxReflectionCaptureComponent). Engine/Shaders/Private/
// ReflectionEnvironmentShared.ush, GetLookupVectorForBoxCapture(): the ray goes into the box's
// local space "where it is an AABB with mins at -1 and maxs at 1" (BoxTransform = inverse of the
// component's transform with scale), so Scale 3D is the box's half-extent in cm; the lookup is
// hit - (capture position + CaptureOffset), CaptureOffset being "World space offset to apply
// before capturing" (UReflectionCaptureComponent::CaptureOffset): world axes, not the actor's.
// The fade (BoxScales.w = BoxTransitionDistance, cm): "Shrink the box by the transition distance
// so that the fade happens inside the box influence area": weight = 1 - smoothstep(0, 0.7 T,
// distance to the box shrunk by T / 2), so full weight from T / 2 inside each face, about 0.20
// on the face itself, 0 only 0.2 T outside it (docs "Reflection Environment": Box Transition
// Distance fades inside the box).
struct UnrealBoxReflectionCapture {
  EngineSource source;
  glm::dvec3 location{0.0};            // cm: the box centre
  glm::dquat rotation{1, 0, 0, 0};     // actor rotation, Unreal axes
  glm::dvec3 scale3D{1.0};             // = box half-extents, cm
  glm::dvec3 captureOffset{0.0};       // cm, Unreal world axes: capture point - location
  double boxTransitionDistance = 0.0;  // cm: transitionDistanceMeters(influence)
};

// Unreal SphereReflectionCapture: InfluenceRadius (cm) is both the area that receives the
// reflection and the sphere it is reprojected onto (UE docs "Reflection Environment"), centred on
// the actor (GetLookupVectorForSphereCapture, ReflectionEnvironmentShared.ush); the capture
// point again via CaptureOffset. Only a true sphere (equal radii).
struct UnrealSphereReflectionCapture {
  EngineSource source;
  glm::dvec3 location{0.0};       // cm: the sphere centre
  double influenceRadius = 0.0;   // cm
  glm::dvec3 captureOffset{0.0};  // cm, Unreal world axes
};

// Godot ReflectionProbe with box_projection. The shader (Godot 3: drivers/gles3/shaders/
// scene.glsl; Godot 4: servers/rendering/renderer_rd/shaders/forward_clustered/
// scene_forward_lights_inc.glsl; both reflection_process()): local_pos = local_matrix * vertex
// (the node's inverse transform), inside where |local_pos| <= box_extents, hit = local_pos +
// nrdir * t against +-box_extents, lookup = hit - box_offset. So the box is centred on the node,
// box_extents are half-sizes (Godot 3 `extents`; Godot 4 `size` = 2 x extents) and origin_offset
// is the capture point in the node's own frame. ReflectionProbe::set_origin_offset /
// set_extents (scene/3d/reflection_probe.cpp) clamp each component to |offset| <= extents -
// 0.01, so a capture point closer than 1 cm to a face, or outside the box, moves: then `exact`
// is false. The node ignores scale (set_disable_scale(true)); its basis carries the rotation.
// Blend: Godot 4.3+ `blend_distance` fades per axis over min(blend_distance, extent) inside the
// box, weights multiplied then squared; Godot 3 has no blend distance (its weight is a fixed
// curve of |local_pos / extents|): the Godot 3 importer keeps it as node metadata.
// Capture: Godot renders each cube face with its far plane at MAX(max_distance, the distance
// from the capture point to the box's face along that axis) (_render_reflection_probe_step);
// with max_distance 0, Godot's default, a wall the box was fitted to lies on the far plane and
// is clipped: the probe shows its clear colour where its own room's walls are. `max_distance`
// is the distance from the capture point to the box's farthest corner, rounded up to the
// millimetre: everything inside the box is in the cubemap.
struct GodotReflectionProbe {
  EngineSource source;
  glm::dvec3 origin{0.0};           // node Transform origin: the box centre, metres
  glm::dquat rotation{1, 0, 0, 0};  // node basis, Godot axes
  glm::dvec3 size{0.0};             // full size in the node's frame, metres (Godot 3: extents
                                    // = size / 2)
  glm::dvec3 originOffset{0.0};     // capture point - origin, in the node's frame, metres
  double blendDistance = 0.0;       // metres: transitionDistanceMeters(influence)
  double maxDistance = 0.0;         // metres: ReflectionProbe.max_distance (0: Godot's default)
  bool boxProjection = true;
  bool exact = true;
};

// Bevy light probe (LightProbe + EnvironmentMapLight): "conceptually a unit cube (1x1x1)
// centered on the origin" under the entity's Transform (bevy_light, LightProbe), so scale =
// full size. Reflection probes are parallax-corrected by default against that same cube
// (ParallaxCorrection::Auto "equivalent to ParallaxCorrection::Custom(Vec3::splat(0.5))", half
// extents in light-probe space; release notes "Parallax Corrected Cubemaps", Bevy PR 22582).
// The lookup is made in the cube's own scaled, turned space from its centre (engine_bevy.cpp
// cites compute_cubemap_sample_dir): it is the true direction only for a cube, not turned, with
// the capture point at the centre: `exact` says so; `captureAtCentre` says whether the cubemap
// can be used as captured or must be re-captured at `translation`.
struct BevyLightProbe {
  EngineSource source;
  glm::dvec3 translation{0.0};      // the box centre, metres
  glm::dquat rotation{1, 0, 0, 0};  // Bevy axes
  glm::dvec3 scale{1.0};            // full size, metres
  glm::dvec3 falloff{0.0};          // LightProbe::falloff, per axis in [0, 1]: fade = falloff *
                                    // scale / 2 inside each face; transitionDistanceMeters
  bool captureAtCentre = true;
  bool exact = true;
};

// Blender 3.x EEVEE Reflection Cubemap light probe (eevee_lightprobes.c,
// EEVEE_lightprobes_cube_data_from_object): Blender's axes are the world's (Z up, metres). The
// object's location is the capture point and the centre of both volumes; the influence is the
// object's transform scaled by influence_distance (1 here, so Object.scale holds the influence's
// half-extents, or its radius for an ellipsoid), fading over `falloff` of the way to each face
// (along Z too); the custom parallax volume is the same transform scaled by parallax_distance:
// a uniformly scaled copy. Made from the scene's influence volume (covered whole from the
// capture point: each half-extent the capture point's larger distance to that axis' faces),
// its fade (transitionDistanceMeters over the shortest half-extent) and the box the other box
// engines get (parallax_distance fitted in least squares to the capture point's mean distance
// to that box's faces along each axis).
struct EeveeReflectionCubemap {
  EngineSource source;
  glm::dvec3 location{0.0};         // Object.location: the capture point, metres
  glm::dquat rotation{1, 0, 0, 0};  // Object.rotation_quaternion
  glm::dvec3 scale{1.0};            // Object.scale: the influence's half-extents (radius x3)
  bool sphere = false;              // LightProbe.influence_type: 'BOX' or 'ELIPSOID'
  double falloff = 1.0;             // LightProbe.falloff, in (0, 1]
  double parallaxDistance = 1.0;    // LightProbe.parallax_distance (use_custom_parallax,
                                    // parallax_type 'BOX')
};

// Which shape each engine gets (make_runtime_export.cpp, enginesFor): the kept proxy when it is
// a box (keptBox); Unity only when that box is also axis-aligned. Otherwise, as before, the
// candidate of the kind the engine takes with the lowest p95. Empty where there is none.
struct RuntimeEngines {
  std::optional<UnityReflectionProbe> unity;                  // kept box if aabb, else best `aabb`
  std::optional<UnityHdrpReflectionProbe> unityHdrp;          // proxy: the box Unreal gets
  std::optional<UnrealBoxReflectionCapture> unrealBox;        // kept box, else best `aabb`/`obb`
  std::optional<UnrealSphereReflectionCapture> unrealSphere;  // best true sphere
  std::optional<GodotReflectionProbe> godot;                  // kept box, else best `aabb`/`obb`
  std::optional<GodotReflectionProbe> godot4;   // the same for Godot 4, whose layout may differ
  std::optional<BevyLightProbe> bevy;           // kept box, else best `aabb`/`obb`
  std::optional<EeveeReflectionCubemap> eevee;  // parallax fitted to that box
};

// One small free function per engine (engine_<name>.cpp). World frame in, engine frame out.
UnityReflectionProbe unityReflectionProbe(const BoxShape& aabb, glm::dvec3 captureMeters,
                                          const InfluenceVolume& influence);
UnityHdrpReflectionProbe unityHdrpReflectionProbe(const BoxShape& proxy, glm::dvec3 captureMeters,
                                                  const InfluenceVolume& influence);
// `inside`: the influence, in plan, the largest centred on the capture point inside the scene's
// outer range, not the smallest holding it (in height it holds the range, floor included).
EeveeReflectionCubemap eeveeReflectionCubemap(const BoxShape& proxy, glm::dvec3 captureMeters,
                                              const InfluenceVolume& influence,
                                              bool inside = false);
// EEVEE captured at the box's centre, where its one transform can hold the box exactly: the
// parallax volume is the box, the influence the box grown about its centre so that it has full
// weight over the whole box and fades to nothing `transitionMeters` beyond its shortest side
// (farther beyond the longer sides: EEVEE's falloff is a share of each half-extent).
EeveeReflectionCubemap eeveeReflectionCubemapAtBoxCentre(const BoxShape& box,
                                                         double transitionMeters);
UnrealBoxReflectionCapture unrealBoxReflectionCapture(const BoxShape& box, glm::dvec3 captureMeters,
                                                      const InfluenceVolume& influence);
UnrealSphereReflectionCapture unrealSphereReflectionCapture(const SphereShape& sphere,
                                                            glm::dvec3 captureMeters);
GodotReflectionProbe godotReflectionProbe(const BoxShape& box, glm::dvec3 captureMeters,
                                          const InfluenceVolume& influence);
BevyLightProbe bevyLightProbe(const BoxShape& box, glm::dvec3 captureMeters,
                              const InfluenceVolume& influence);

// The one fade distance Unreal's BoxTransitionDistance and Godot's blend_distance take, from the
// influence's fade (outer minus inner range, per axis for a box), metres.
//
// Rule: the smallest fade over the axes that fade at all (0 only when none does; a sphere's
// is radius - inner radius). Both engines fade one distance inward from every face of the box
// (Godot: per axis, clamped to the extent, weights multiplied; Unreal: "fades in over the
// transition distance ... inside the box", UE docs "Reflection Captures"). Our influence may
// fade along one axis and not the others (a room between two probes along X: fade 1.45 m in
// X, 0 in Y and Z); the old rule, the smallest over all three axes, gave 0 there: a hard cut.
// Loss, stated: (1) along the axes with no fade (walls) the engine still fades over this
// distance inside the box, where Lagarde's weight stays 1; (2) along axes with a wider fade
// the engine's transition is narrower; (3) the engine fades inside the exported box (the
// proxy), not inside our influence volume, whose extent it does not have.
double transitionDistanceMeters(const InfluenceVolume& influence);

}  // namespace probeproxy
