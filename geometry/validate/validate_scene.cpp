#include "geometry/validate/validate_scene.h"

#include "core/errors/option_checks.h"
#include "geometry/probe_proxies/authored_proxy_shape.h"
#include "geometry/validate/validation_rules.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace probeproxy {

namespace {

bool hasError(const std::vector<ValidationFinding>& findings, std::size_t from) {
  return std::any_of(findings.begin() + static_cast<std::ptrdiff_t>(from), findings.end(),
                     [](const ValidationFinding& f) { return f.severity == "error"; });
}

}  // namespace

void ValidateOptions::check() const {
  requirePositive("tolerance_deg", toleranceDeg);
  requireInRange("max_overlap", maxOverlap, 1, 64);
  requireNonNegative("max_inner_overlap_m3", maxInnerOverlapCubicMeters);
  requireNonNegative("max_uncovered_m2", maxUncoveredFloorSquareMeters);
  requirePositive("max_weight_jump", maxWeightJumpPerCentimeter);
  requireInRange("weight_grid_m", weightGridMeters, 1e-3, 1.0);
  requireInRange("max_leak_share", maxLeakShare, 0.0, 1.0);
  requireInRange("grid", gridSpacingMeters, 0.01, 10.0);
  requireInRange<std::size_t>("grid_point_budget", gridPointBudget, 1, 100'000'000);
  walkedFloor.check();
  samples.check();
  for (const std::string& rule : rules) {
    if (std::find(kSelectableRules.begin(), kSelectableRules.end(), rule) != kSelectableRules.end())
      continue;
    throw InputError("option rules",
                     "unknown rule '" + rule + "' (rules: " + selectableRuleNames() + ")");
  }
}

std::string selectableRuleNames() {
  std::string names;
  for (std::string_view r : kSelectableRules) names += (names.empty() ? "" : ", ") + std::string(r);
  return names;
}

bool ValidateOptions::measures(std::string_view rule) const {
  return rules.empty() || std::find(rules.begin(), rules.end(), rule) != rules.end();
}

std::vector<ValidationFinding> validateScene(const Scene& scene, const LevelRayCaster& level,
                                             const ValidateOptions& options) {
  options.check();
  std::vector<ValidationFinding> findings;
  // The walkable floor is walked for the rules that measure on it only.
  const bool onFloor = options.measures("split_probe") || options.measures("influence_leak") ||
                       options.measures("reflected_camera_outside_proxy") ||
                       options.measures("floor_not_covered") ||
                       options.measures("too_many_overlaps") || options.measures("weight_jump");
  const WalkableFloor walked = onFloor ? walkedFloor(scene, level, options) : WalkableFloor{};
  const std::vector<FloorCell>& floor = walked.cells;
  std::vector<InfluenceVolume> volumes;
  for (const Probe& probe : scene.probes) volumes.push_back(probe.influence);
  // Each probe's rules read only the level and the scene (a probe's proxy build is most of a
  // validate on a laid-out map): the probes run in parallel, their findings in probe order.
  std::vector<std::vector<ValidationFinding>> perProbe(scene.probes.size());
  tbb::parallel_for(std::size_t{0}, scene.probes.size(), [&](std::size_t index) {
    const Probe& probe = scene.probes[index];
    std::vector<ValidationFinding>& found = perProbe[index];
    // Later rules measure what earlier ones establish: a proxy that is not a closed convex
    // mesh, or that misses its capture point, has no meaningful error yet; a capture point
    // outside its influence volume has no samples. Fix those first, then see the rest.
    checkAuthoredMesh(scene, probe, found);
    const std::optional<ProxyShape> authored = authoredProxyShape(probe.proxy, scene);
    if (authored && !hasError(found, 0)) checkCaptureInsideProxy(probe, *authored, found);
    checkCaptureInsideInfluence(probe, found);
    if (hasError(found, 0)) return;
    if (options.measures("capture_outside_level")) checkCaptureInsideLevel(level, probe, found);
    if (authored &&
        (options.measures("proxy_error_over_tolerance") || options.measures("split_probe")))
      checkProxyError(level, probe, volumes, static_cast<int>(index), *authored, floor, options,
                      found);
    // Cameras over the floor behind the wall a volume leaks through are outside any proxy of
    // this probe's room: that is the leak, reported once.
    std::vector<ValidationFinding> leak;
    const bool cameras = authored && options.measures("reflected_camera_outside_proxy");
    if (cameras || options.measures("influence_leak"))
      checkInfluenceLeak(level, probe, floor, options, leak);
    if (options.measures("influence_leak")) found.insert(found.end(), leak.begin(), leak.end());
    if (cameras && leak.empty()) checkReflectedCameras(level, probe, *authored, options, found);
  });
  for (std::vector<ValidationFinding>& found : perProbe)
    findings.insert(findings.end(), std::make_move_iterator(found.begin()),
                    std::make_move_iterator(found.end()));
  if (options.measures("too_many_overlaps")) checkOverlaps(scene, level, walked, options, findings);
  // Overlapping inner ranges make the weights jump where one range ends (both claim 100%):
  // that is one problem, reported once.
  std::vector<ValidationFinding> inner;
  if (options.measures("inner_ranges_overlap") || options.measures("weight_jump"))
    checkInnerRanges(scene, options, inner);
  if (options.measures("inner_ranges_overlap"))
    findings.insert(findings.end(), inner.begin(), inner.end());
  if (inner.empty() && options.measures("weight_jump"))
    checkWeightJumps(scene, level, walked, options, findings);
  if (options.measures("floor_not_covered")) checkFloorCoverage(scene, floor, options, findings);
  return findings;
}

bool findingsFail(const std::vector<ValidationFinding>& findings) {
  return std::any_of(findings.begin(), findings.end(),
                     [](const ValidationFinding& f) { return f.severity != "info"; });
}

}  // namespace probeproxy
