// influence_leak: an influence volume that reaches through a wall lights space its probe has
// never seen (light leaking). Measured on the walkable floor inside the volume: the share of
// the probe's influence (Lagarde's factor, core/blend) that falls on floor hidden from it, so
// a fade band reaching round a corner counts for what it contributes there.

#include "core/blend/influence_factor.h"
#include "geometry/validate/validation_rules.h"

#include <cstdio>

namespace probeproxy {

namespace {

// A wall hides space from every point of view near the capture point and at every height;
// a pillar or a crate only from some. So a floor point counts as hidden when none of a few
// viewpoints (the capture point and points up to kViewOffsetMeters beside it, short of any
// wall) sees the room above it just under the ceiling (at most kHighestTargetMeters up).
constexpr double kViewOffsetMeters = 1.5;
constexpr double kWallGapMeters = 0.2;
constexpr double kUnderCeilingMeters = 0.1;
constexpr double kHighestTargetMeters = 10.0;
constexpr double kInsideLiftMeters = 0.05;  // floor points sit on the volume's boundary

std::vector<glm::dvec3> viewpoints(const LevelRayCaster& level, glm::dvec3 capture) {
  std::vector<glm::dvec3> points{capture};
  for (const glm::vec3 d :
       {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0)}) {
    Ray ray{capture, d, 0.0f, static_cast<float>(kViewOffsetMeters + kWallGapMeters)};
    const RayHit hit = level.firstHit(ray);
    const double reach = hit.hit() ? hit.t - kWallGapMeters : kViewOffsetMeters;
    if (reach > 0.0) points.push_back(capture + reach * glm::dvec3(d));
  }
  return points;
}

bool seenFromAny(const LevelRayCaster& level, const std::vector<glm::dvec3>& from,
                 glm::dvec3 target) {
  for (const glm::dvec3& v : from) {
    Ray ray{v, glm::vec3(target - v), 0.0f, 0.999f};
    if (!level.firstHit(ray).hit()) return true;
  }
  return false;
}

}  // namespace

void checkInfluenceLeak(const LevelRayCaster& level, const Probe& probe,
                        const std::vector<FloorCell>& floor, const ValidateOptions& options,
                        std::vector<ValidationFinding>& out) {
  const std::vector<glm::dvec3> from = viewpoints(level, probe.captureMeters);
  double total = 0.0, hidden = 0.0;
  glm::dvec3 firstHidden(0.0);
  for (const FloorCell& f : floor) {
    const double factor =
        influenceFactor(probe.influence, f.pointMeters + glm::dvec3(0, 0, kInsideLiftMeters));
    if (factor <= 0.0) continue;
    total += factor;
    Ray up{f.pointMeters, {0.0f, 0.0f, 1.0f}, 1e-3f, static_cast<float>(kHighestTargetMeters)};
    const RayHit ceiling = level.firstHit(up);
    const double height = ceiling.hit() ? ceiling.t - kUnderCeilingMeters : kHighestTargetMeters;
    if (seenFromAny(level, from, f.pointMeters + glm::dvec3(0, 0, height))) continue;
    if (hidden == 0.0) firstHidden = f.pointMeters;
    hidden += factor;
  }
  if (total == 0.0) return;
  const double share = hidden / total;
  if (share <= options.maxLeakShare) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "' influence volume: %.1f%% of its influence on walkable floor falls behind a "
                "wall from the capture point, e.g. at ",
                100.0 * share);
  out.push_back({probe.name, "influence_leak", "warning", share, options.maxLeakShare,
                 "probe '" + probe.name + text + formatPoint(firstHidden),
                 "shrink or rotate the influence volume so it stays in the space the probe "
                 "sees, and give the space behind the wall a probe of its own"});
}

}  // namespace probeproxy
