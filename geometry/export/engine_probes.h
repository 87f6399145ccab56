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

// Unity ReflectionProbe with box projection (ScriptReference: ReflectionProbe.center "relative
// to the position of the probe", ReflectionProbe.size "in world space", boxProjection). The
// box is axis-aligned in Unity's world: Unity ignores the probe's rotation, so only an `aabb`
// candidate is exported. The box is both the influence and the projection volume.
struct UnityReflectionProbe {
  EngineSource source;
  glm::dvec3 position{0.0};  // Transform.position: the capture point, metres
  glm::dvec3 center{0.0};    // ReflectionProbe.center: box centre - position, metres
  glm::dvec3 size{0.0};      // ReflectionProbe.size: full size (2 x half-extents), metres
  bool boxProjection = true;
};

// Unreal BoxReflectionCapture (UBoxReflectionCaptureComponent): the capture box is a box of
// extent 1 (InitBoxExtent(1, 1, 1)) under the actor's transform, so the actor scale is the
// box's half-extents in cm; the cubemap is captured at location + CaptureOffset ("world space
// offset to apply before capturing"); BoxTransitionDistance (cm, default 100) fades the
// influence in, inside the box (UE docs "Reflection Captures": "fades in over the transition
// distance as well, inside the box").
struct UnrealBoxReflectionCapture {
  EngineSource source;
  glm::dvec3 location{0.0};            // cm: the box centre
  glm::dquat rotation{1, 0, 0, 0};     // actor rotation, Unreal axes
  glm::dvec3 scale3D{1.0};             // = box half-extents, cm
  glm::dvec3 captureOffset{0.0};       // cm, Unreal world axes: capture point - location
  double boxTransitionDistance = 0.0;  // cm: transitionDistanceMeters(influence), applied
                                       // inside the box on every axis, as Unreal does
};

// Unreal SphereReflectionCapture: InfluenceRadius (cm) is both the area that receives the
// reflection and the sphere it is reprojected onto (UE docs "Reflection Captures"), centred on
// the actor; the capture point again via CaptureOffset. Only a true sphere (equal radii).
struct UnrealSphereReflectionCapture {
  EngineSource source;
  glm::dvec3 location{0.0};       // cm: the sphere centre
  double influenceRadius = 0.0;   // cm
  glm::dvec3 captureOffset{0.0};  // cm, Unreal world axes
};

// Godot 4 ReflectionProbe with box_projection: `size` is the full size of a box centred on the
// node (Godot 3's `extents` were half-sizes), `origin_offset` moves the capture point in the
// node's own frame; the node's transform carries the rotation. Godot clamps each component of
// origin_offset to size / 2 - 0.01 (ReflectionProbe::set_origin_offset), so a capture point
// closer than 1 cm to a face, or outside the box, is moved: then `exact` is false.
struct GodotReflectionProbe {
  EngineSource source;
  glm::dvec3 origin{0.0};           // node Transform3D origin: the box centre, metres
  glm::dquat rotation{1, 0, 0, 0};  // node basis, Godot axes
  glm::dvec3 size{0.0};             // full size in the node's frame, metres
  glm::dvec3 originOffset{0.0};     // capture point - origin, in the node's frame, metres
  double blendDistance = 0.0;       // metres: transitionDistanceMeters(influence); Godot 4.3+
                                    // fades the probe over it inside the box on every axis
  bool boxProjection = true;
  bool exact = true;
};

// Bevy light probe (LightProbe + EnvironmentMapLight): "conceptually a unit cube (1x1x1)
// centered on the origin" under the entity's Transform, so scale = full size. Since Bevy 0.19
// reflection probes are parallax-corrected by default against that same box
// (ParallaxCorrection::Auto, release notes "Parallax Corrected Cubemaps");
// ParallaxCorrection::Custom(half-extents) is also centred on the probe. Bevy projects from the
// probe's centre (LightProbe.world_position): with the capture point elsewhere `exact` is false
// and the cubemap should be re-captured at `translation`.
struct BevyLightProbe {
  EngineSource source;
  glm::dvec3 translation{0.0};      // the box centre, metres
  glm::dquat rotation{1, 0, 0, 0};  // Bevy axes
  glm::dvec3 scale{1.0};            // full size, metres
  bool exact = true;
};

// Which shape each engine gets (make_runtime_export.cpp, enginesFor): the kept proxy when it is
// a box (keptBox); Unity only when that box is also axis-aligned. Otherwise, as before, the
// candidate of the kind the engine takes with the lowest p95. Empty where there is none.
struct RuntimeEngines {
  std::optional<UnityReflectionProbe> unity;                  // kept box if aabb, else best `aabb`
  std::optional<UnrealBoxReflectionCapture> unrealBox;        // kept box, else best `aabb`/`obb`
  std::optional<UnrealSphereReflectionCapture> unrealSphere;  // best true sphere
  std::optional<GodotReflectionProbe> godot;                  // kept box, else best `aabb`/`obb`
  std::optional<BevyLightProbe> bevy;                         // kept box, else best `aabb`/`obb`
};

// One small free function per engine (engine_<name>.cpp). World frame in, engine frame out.
UnityReflectionProbe unityReflectionProbe(const BoxShape& aabb, glm::dvec3 captureMeters);
UnrealBoxReflectionCapture unrealBoxReflectionCapture(const BoxShape& box, glm::dvec3 captureMeters,
                                                      const InfluenceVolume& influence);
UnrealSphereReflectionCapture unrealSphereReflectionCapture(const SphereShape& sphere,
                                                            glm::dvec3 captureMeters);
GodotReflectionProbe godotReflectionProbe(const BoxShape& box, glm::dvec3 captureMeters,
                                          const InfluenceVolume& influence);
BevyLightProbe bevyLightProbe(const BoxShape& box, glm::dvec3 captureMeters);

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
