#pragma once
// Validation of the volumes an artist authored (docs/validation.md): every
// rule below looks at the scene and the real level and reports what breaks it, which probe,
// by how much, and how to fix it. A clean scene gives no findings. The CLI (`probeproxy
// validate`) and the Blender add-on both call validateScene.
//
// Rules (id, severity, value / limit; docs/validation.md has the full table):
//   proxy_* (the OpenMesh checks of geometry/validate/proxy_mesh_checks.h, on an authored
//     `convex` mesh: proxy_not_closed, proxy_concave_edge, proxy_not_convex, ...)   error
//   capture_outside_proxy       error    metres the capture point lies outside its authored
//                                        proxy (signed, negative inside) / 0
//   capture_outside_influence   error    metres outside its influence volume's outer range / 0
//   capture_outside_level       warning  share of the capture point's directions that see no
//                                        level or the back of a surface / 0.5
//   proxy_error_over_tolerance  warning  the authored proxy's mirror_floor p95 angular error,
//                                        degrees / tolerance; the message gives the generated
//                                        proxy's p95 beside it
//   floor_not_covered           warning  walkable floor (upward-facing, with head room) in no
//                                        influence volume, m^2 / limit
//   too_many_overlaps           warning  most outer ranges covering one point / max overlap
//   inner_ranges_overlap        warning  volume where two inner ranges overlap, m^3 / limit
//   weight_jump                 warning  largest blend-weight change between neighbouring
//                                        grid points, per centimetre / limit
//   influence_leak              warning  share of the influence volume's walkable floor the
//                                        capture point cannot see (through a wall) / limit
//   reflected_camera_outside_proxy  warning  metres the camera reflected through a planar
//                                        receiver lies outside the proxy / 0 (Lagarde & Zanuttini's
//                                        glossy rule: enlarge the proxy)

#include "core/blend/blend_weights.h"
#include "core/scene/scene.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/floor/walkable_floor.h"
#include "geometry/raycast/level_ray_caster.h"

#include <glm/vec3.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

struct ValidationFinding {
  std::string probe;     // the probe it is about (for pairs: the first in scene order)
  std::string rule;      // stable id, see the list above
  std::string severity;  // "error", "warning" or "info"
  double value = 0.0;    // the measured amount, in the unit the rule list gives
  double limit = 0.0;    // the limit it broke
  std::string message;   // one line: what is wrong, naming the probe(s) and where
  std::string hint;      // one line: how to fix it
};

// The rules ValidateOptions::rules may name.
inline constexpr std::array<std::string_view, 9> kSelectableRules = {
    "capture_outside_level",
    "proxy_error_over_tolerance",
    "split_probe",
    "influence_leak",
    "reflected_camera_outside_proxy",
    "too_many_overlaps",
    "inner_ranges_overlap",
    "weight_jump",
    "floor_not_covered"};

// kSelectableRules, comma-separated: for the rules option's help and its error.
std::string selectableRuleNames();

struct ValidateOptions {
  // proxy_error_over_tolerance: the authored proxy's mirror_floor p95 may be at most this.
  double toleranceDeg = 0.25;
  // too_many_overlaps: at most this many outer ranges may cover one point: the blend's own
  // limit (Lagarde & Zanuttini 2012: "We set the limit to 4 in our game. This can cause lighting
  // pop when 5 volumes overlap").
  int maxOverlap = kDefaultMaxBlendProbes;
  // inner_ranges_overlap: overlapping inner ranges may share at most this volume.
  double maxInnerOverlapCubicMeters = 0.0;
  // floor_not_covered: uncovered walkable floor may add up to at most this area.
  double maxUncoveredFloorSquareMeters = 0.5;
  // weight_jump: blend weights may change at most this much per centimetre between
  // neighbouring grid points.
  double maxWeightJumpPerCentimeter = 0.02;
  // weight_jump: spacing of the horizontal grid the weights are compared on.
  double weightGridMeters = 0.01;
  // weight_jump, too_many_overlaps: a camera is at most this far over the walked floor under it
  // (eye height, 1.7 m, and a jump); higher, in the air over a pit or a hall, it only falls.
  double cameraHeadRoomMeters = 2.5;
  // influence_leak: at most this share of an influence volume's walkable floor may be
  // hidden from its capture point.
  double maxLeakShare = 0.05;
  // Grid spacing for the floor, overlap and leak rules; coarsened on huge levels so no rule
  // tests more than about gridPointBudget points.
  double gridSpacingMeters = 0.25;
  std::size_t gridPointBudget = 2'000'000;
  // The walked floor's player (step height, head clearance); its grid is gridSpacingMeters.
  WalkableFloorOptions walkedFloor;
  // reflected_camera_outside_proxy: the receivers are glossy (perturbed normals reach below
  // the plane), so the reflected camera itself must be inside the proxy (Lagarde & Zanuttini 2012);
  // for mirrors only the receiver under each camera must be.
  bool glossyReceivers = false;
  // Where a player enters the level (its spawn points): the floor the floor, error and leak
  // rules measure on is the floor reached from them (the probes' capture points when empty).
  std::vector<glm::dvec3> seedPointsMeters;
  // Samples and cameras of proxy_error_over_tolerance and reflected_camera_outside_proxy.
  ReflectionSampleOptions samples;
  // The rules measured, by id (kSelectableRules); empty: all. The mesh and capture checks
  // (proxy_*, capture_outside_proxy, capture_outside_influence) always run: they decide whether
  // a probe's other rules can be measured at all. On a real map's layout the proxy error rule
  // and its split_probe search take nearly all of validate's time (darkzone: 225 s), so the
  // volume rules alone are a quick check.
  std::vector<std::string> rules;
  bool measures(std::string_view rule) const;

  // Throws InputError naming the first option outside its range (the CLI flags' names in
  // snake_case): tolerance_deg > 0, max_overlap in [1, 64], max_inner_overlap_m3 >= 0,
  // max_uncovered_m2 >= 0, max_weight_jump > 0, max_leak_share in [0, 1], grid in
  // [0.01, 10], samples in [64, 1000000], every rule one of kSelectableRules.
  void check() const;
};

// Findings in a fixed order: per probe in scene order (mesh checks, capture, error, leak,
// reflected camera unless the volume leaks), then the scene-wide rules (overlaps, inner ranges,
// weights, floor). Deterministic. Throws InputError for an authored proxy mesh that cannot be read.
std::vector<ValidationFinding> validateScene(const Scene& scene, const LevelRayCaster& level,
                                             const ValidateOptions& options = {});

// Whether findings should fail a pipeline: any error or warning (info alone does not).
bool findingsFail(const std::vector<ValidationFinding>& findings);

}  // namespace probeproxy
