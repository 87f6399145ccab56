#pragma once
// The runtime export (docs/cli_and_formats.md "Runtime export"): `proxies.json` + `proxies.glb`,
// files a game engine loads without this library. RuntimeExport is what proxies.json holds, in
// the world frame (Z up, metres), so that readRuntimeExport gives back what was written.
//
// proxies.json, format id "probeproxy_runtime", version 1
// -------------------------------------------------------
// Coordinates are in the scene file's frame and unit (`up`, `meters_per_unit` copied from
// it), so the engine side sees what the artist declared; a loader converts back as the scene
// file's reader does: metres = value * meters_per_unit, and a Y-up point (x, y, z) is the
// Z-up point (x, -z, y). Rotations are unit quaternions [w, x, y, z] taking a shape's own
// frame to the file's frame; boxes store half-extents along their own axes (with Y up, a box's
// own axes turn with the file's: Y-up half-extents (x, y, z) are Z-up (x, z, y)). Members
// appear in the order below. `null` stands for a figure that was not measured (NaN).
//
// {
//   "probeproxy_runtime": 1,
//   "up": "Z",                           // or "Y"
//   "meters_per_unit": 1.0,
//   "mesh_file": "proxies.glb",          // one node "<probe name>_proxy" per probe whose proxy
//                                        // has a volume; glTF: metres, Y up
//   "probes": [ {
//     "name": "corridor_a",
//     "capture": [x, y, z],              // the cubemap's centre
//     "kind": "obb",                     // the method a shader runs: infinite, cheap_k, sphere,
//                                        // aabb, obb or convex
//     "candidate": "obb",                // the build candidate it is: authored, hull, convex_12..
//     "k": 0.5,                          // cheap_k only, per file unit: the lookup is
//                                        // normalize(k * (x - capture) + r)
//     "box": { "center", "half_extents", "rotation" },  // aabb and obb only
//     "sphere": { "center", "radii", "rotation" },      // sphere only (an ellipsoid if radii
//                                                       // differ)
//     "world_to_unit": [[4 numbers], [..], [..], [0.0, 0.0, 0.0, 1.0]],
//                                        // aabb, obb, sphere only: row-major, unit = M * [x, y,
//                                        // z, 1] maps the box to [-1, 1]^3 (Lagarde & Zanuttini's
//                                        unit box
//                                        // space), the sphere to the unit sphere (Bjorke's
//                                        // lighting space); file frame in, the shape's own axes
//                                        // out
//     "planes_count": 6,                 // planes a shader tests: 0 for infinite, cheap_k and
//                                        // sphere, 6 for boxes, k for convex
//     "planes": [[nx, ny, nz, d], ..],   // outward unit normal n, inside where n . x <= d;
//                                        // [] for infinite, cheap_k and sphere
//     "vertices": [[x, y, z], ..],       // the proxy's boundary; [] for infinite and cheap_k
//     "triangles": [[a, b, c], ..],      // 0-based into vertices, counter-clockwise from outside
//     "mesh_is_display_only": false,     // true for sphere: an icosphere (162 vertices) on the
//                                        // sphere to look at, not what the method intersects
//     "influence": { "kind": "box", "center", "half_extents", "rotation", "inner_half_extents" }
//               or { "kind": "sphere", "center", "radius", "inner_radius" },
//                                        // Lagarde's blend: 100% inside the inner range, fading
//                                        // to 0% at the outer one
//     "blend": { "enlighten": { "epsilon": 0.000001, "box": { "center", "half_extents",
//                                                           "rotation" } } },
//                                        // Enlighten's weight 1 / (epsilon + distSq), distSq the
//                                        // squared distance (file units) from the point to the
//                                        // box, measured in the box's own frame; the box is the
//                                        // influence's outer range (a sphere's bounding cube)
//     "error": { "median_deg", "p95_deg", "max_deg", "miss_rate", "occluded_rate", "samples" },
//                                        // of the kept proxy, on the mirror_floor sample set
//     "engines": {                       // for runtimes that take only a box or a sphere; each
//                                        // is null when no candidate of that kind was built.
//                                        // Engine frames and units, see engine_probes.h;
//                                        // quaternions [x, y, z, w]; each entry has "candidate",
//                                        // "kept_proxy" and "error" of the candidate it was made
//                                        // from: kept_proxy true when it is the kept proxy
//                                        // (a box, or a convex within 1 um of one, kept_box.h)
//       "unity_reflection_probe": { .., "position", "center", "size", "blend_distance",
//                                   "box_projection" },
//       "unity_hdrp_reflection_probe": { .., "position", "rotation_xyzw", "influence_shape",
//                                        "box_size", "box_blend_distance_positive",
//                                        "box_blend_distance_negative" (box) or
//                                        "sphere_radius", "sphere_blend_distance" (sphere),
//                                        "capture_position", "proxy_position",
//                                        "proxy_rotation_xyzw", "proxy_size" },
//       "unreal_box_reflection_capture": { .., "location", "rotation_xyzw", "scale_3d",
//                                          "capture_offset", "box_transition_distance" },
//       "unreal_sphere_reflection_capture": { .., "location", "influence_radius",
//                                             "capture_offset" },
//       "godot_reflection_probe": { .., "origin", "rotation_xyzw", "size", "origin_offset",
//                                   "blend_distance", "box_projection", "exact" },
//       "godot4_reflection_probe": { ..the same, for Godot 4 },
//       "bevy_light_probe": { .., "translation", "rotation_xyzw", "scale", "falloff",
//                             "parallax_correction": "auto", "capture_at_centre", "exact" },
//       "eevee_reflection_cubemap": { .., "location", "rotation_xyzw", "scale",
//                                     "influence_type", "influence_distance": 1, "falloff",
//                                     "use_custom_parallax": true, "parallax_type": "BOX",
//                                     "parallax_distance" }
//     }
//   } ]
// }
//
// The box engines get the kept proxy when it is a box (Unity: an axis-aligned one); otherwise
// Unity the best `aabb` candidate (lowest p95), the other box engines the best `aabb` or `obb`
// (HDRP as its proxy volume, EEVEE to fit its parallax volume to); Unreal's sphere capture the
// best `sphere` candidate with equal radii. Unity's size is that box shrunk by blend_distance
// (Unity projects on the box grown by it). A reader takes an export without the HDRP and EEVEE
// entries or Unity's blend_distance (earlier exports) as none and Unity's default 1 m, and an
// export without godot4_reflection_probe as giving Godot 4 the Godot 3 entry.
// box_transition_distance (cm) and blend_distance (m): transitionDistanceMeters (engine_probes.h),
// the smallest fade of the influence over the axes that fade; Bevy's falloff is that distance
// over each half-size (clamped to [0, 1]). Numbers in the
// file read back to the same world values (shortest round-trip decimals; a file-unit value is
// rounded to 1e-9 only where that reads back to the same metres); engine numbers are rounded
// to 1e-9 of the engine's unit. Same input, same bytes.

#include "core/blend/enlighten_distance.h"
#include "core/measures/error_figures.h"
#include "core/proxy/proxy_candidate.h"
#include "core/proxy/proxy_shape.h"
#include "core/scene/scene.h"
#include "geometry/export/engine_probes.h"
#include "geometry/level/level_mesh.h"

#include <glm/mat4x4.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

inline constexpr int kRuntimeExportVersion = 1;
inline constexpr char kRuntimeExportFormatId[] = "probeproxy_runtime";
inline constexpr char kProxiesJsonName[] = "proxies.json";
inline constexpr char kProxiesGlbName[] = "proxies.glb";

struct EnlightenBlend {
  double epsilon = kEnlightenEpsilon;
  BoxShape box;  // world frame: the box distSq is measured to
};

struct RuntimeProbe {
  std::string name;
  glm::dvec3 captureMeters{0.0};
  Method method = Method::Infinite;       // what the shader runs: methodOf(kept shape)
  std::string candidate;                  // ProxyCandidate::kind of the kept one
  std::optional<double> kPerMeter;        // cheap_k
  std::optional<BoxShape> box;            // aabb, obb
  std::optional<SphereShape> sphere;      // sphere
  std::optional<glm::dmat4> worldToUnit;  // aabb, obb, sphere: world point -> unit box/sphere
  ConvexProxy convex;  // planes (none for a sphere) and boundary mesh (none without a volume)
  bool meshIsDisplayOnly = false;  // the sphere's icosphere
  int planesCount = 0;             // planeCount(kept shape)
  InfluenceVolume influence;
  EnlightenBlend enlighten;
  ErrorFigures error;  // mirror_floor
  RuntimeEngines engines;
};

struct RuntimeExport {
  UpAxis fileUp = UpAxis::Z;  // the scene file's, written as `up`
  double metersPerUnit = 1.0;
  std::vector<RuntimeProbe> probes;  // in the order of the builds
};

// Every engine box's bottom, and a box influence's, goes at least this far under the floor it
// was fitted to. On a face, an engine's inside test (abs(local) > extents) and its fade (0 on
// the face) are decided by rounding: Godot 3 rendered a floor lying on its probes' bottom faces
// in black and lit streaks along image rows, and the models' figures there were as fragile.
// Reflections off a floor go up, so they never meet the lowered face.
inline constexpr double kFloorClearanceMeters = 0.02;

// The box with its bottom face (world) lowered by `drop` where its own z is the world's
// vertical (an aabb, an obb turned about Z); its top stays. Other boxes are returned as given.
BoxShape withBottomLowered(BoxShape box, double drop);

// How the engine presets are made from each probe's box and influence volume. `build` exports
// the defaults; `layout --engine E` exports the policy its engine renders best (measured).
struct EnginePresetPolicy {
  // The influence's fade (outer minus inner range, per axis) times this: the one fade distance
  // every engine gets (engine_probes.h, transitionDistanceMeters) and HDRP's per-face blends.
  double fadeScale = 1.0;
  // Lower each engine box's bottom face, and a box influence's, by that fade: engines that fade
  // inside the box leave a floor lying near its bottom face to the sky; a mirror floor's
  // reflections go up, so they never meet the lowered face. Only boxes whose own z is the
  // world's vertical (an aabb, an obb turned about Z). Without it the bottom still goes 2 cm
  // under the floor (kFloorClearanceMeters, above): never a floor on a face.
  bool clearTheFloor = false;
  // Cut each engine box, in plan, to the probe's influence volume (outer range): where the box
  // is also where the probe applies (Unity, Unreal, Godot, Bevy), a room-sized box reaches floor
  // other probes serve. Only where the box and the influence are turned alike.
  bool clipToInfluence = false;
  // Bevy: each light probe the cube centred on the capture point (world axes), its half-extent
  // the capture point's mean distance to the box's six faces. Bevy's lookup is right only for an
  // unturned cube captured at its centre; a room that is not a cube is otherwise looked up
  // stretched.
  bool cubeAboutCapture = false;
  // EEVEE: the influence, in plan, the largest box (sphere) centred on the capture point inside
  // the scene's outer range, instead of the smallest holding it (which reaches past the near
  // side); in height it still holds the range, floor included.
  bool influenceInside = false;
  // EEVEE: the probe captured at the centre of its box, which it then holds exactly
  // (eeveeReflectionCubemapAtBoxCentre), instead of at the scene's capture point. `layout
  // --engine eevee` chooses it probe by probe, where the way from the capture point is clear.
  bool eeveeAtBoxCentre = false;

  bool operator==(const EnginePresetPolicy&) const = default;
};

// The export of `builds` (one per probe, each naming a probe of `scene`, in the order given).
// Throws std::invalid_argument for builds that break that contract (unknown or repeated probe,
// `kept` out of range, a non-finite or empty shape) or a fadeScale outside [0, 4].
RuntimeExport makeRuntimeExport(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                                const EnginePresetPolicy& policy = {});

// The bytes of proxies.json. Deterministic.
std::string runtimeExportJson(const RuntimeExport& runtime);

// Writes `outFolder`/proxies.json and proxies.glb. Both are built in memory and written to
// temporary files first; only when both are complete are they renamed into place (proxies.glb
// first, proxies.json last), so neither is ever left half-written.
// Nothing an artist authored is overwritten; InputError (naming the file) if
//   - outFolder holds a proxies.json that is not a probeproxy runtime export,
//   - outFolder holds a proxies.glb but no probeproxy proxies.json beside it,
//   - an output path is the scene file, a level mesh or an authored proxy mesh.
void writeRuntimeExport(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                        const std::filesystem::path& outFolder);
// The same for an export already made (of `scene`'s probes).
void writeRuntimeExport(const Scene& scene, const RuntimeExport& runtime,
                        const std::filesystem::path& outFolder);

// Reads proxies.json back into the world frame. Throws InputError(file, "<JSON path>: <what
// was expected>, got <what was there>") for the first problem, e.g.
// "$.probes[0].capture: expected an array of 3 finite numbers, got "a"".
RuntimeExport readRuntimeExport(const std::filesystem::path& proxiesJson);
RuntimeExport parseRuntimeExport(std::string_view bytes, const std::filesystem::path& file);

// The proxies.glb content: one part "<probe>_proxy" per probe with a boundary mesh, world
// frame (writeLevelMeshFile turns it Y-up).
LevelMesh runtimeExportMesh(const RuntimeExport& runtime);

}  // namespace probeproxy
