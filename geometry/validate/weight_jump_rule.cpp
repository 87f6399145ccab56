// weight_jump: a blend weight that changes abruptly between neighbouring points pops as the
// camera moves (Lagarde's weights, core/blend). Measured on a horizontal grid at each capture
// height, over points at most head room above a floor of the level (volumes reach into walls,
// where nobody stands, and over pits, where a camera only falls), and scaled to a change per
// centimetre so the grid spacing does not move the limit.
// Points inside a solid block are not over a floor even where its bottom face is missing
// (geometry/raycast/open_space.h; basement: two bands met inside a 6 m block).

#include "core/blend/weight_continuity.h"
#include "geometry/raycast/open_space.h"
#include "geometry/validate/validation_rules.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace probeproxy {

void checkWeightJumps(const Scene& scene, const LevelRayCaster& level,
                      const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (scene.probes.empty()) return;
  std::vector<InfluenceVolume> volumes;
  std::set<double> heights;
  for (const Probe& p : scene.probes) {
    volumes.push_back(p.influence);
    heights.insert(p.captureMeters.z);
  }
  const ReachableMask aboveFloor = [&](std::span<const glm::dvec3> points,
                                       std::span<char> reachable) {
    const std::vector<VerticalView> views = lookUpAndDown(level, points);
    for (std::size_t i = 0; i < points.size(); ++i)
      reachable[i] = views[i].floorBelowMeters <= options.weightJumpHeadRoomMeters;
  };
  WeightContinuity worst;
  double worstPerCm = 0.0, worstSpacing = 0.0;
  for (double z : heights) {
    WeightGrid grid = gridOverVolumes(volumes, z, options.weightGridMeters);
    const glm::dvec2 size = grid.maxMeters - grid.minMeters;
    const double points = (size.x / grid.spacingMeters + 1) * (size.y / grid.spacingMeters + 1);
    const double budget = static_cast<double>(options.gridPointBudget);
    if (points > budget)
      grid = gridOverVolumes(volumes, z, options.weightGridMeters * std::sqrt(points / budget));
    const WeightContinuity c = measureWeightContinuity(volumes, grid, {}, aboveFloor);
    const double perCm = c.largestJump / (100.0 * grid.spacingMeters);
    if (perCm > worstPerCm) worstPerCm = perCm, worst = c, worstSpacing = grid.spacingMeters;
  }
  if (worstPerCm <= options.maxWeightJumpPerCentimeter || worst.jumpProbe < 0) return;
  const std::string& name = scene.probes[static_cast<std::size_t>(worst.jumpProbe)].name;
  char text[200];
  std::snprintf(text, sizeof text,
                "' blend weight changes by %.3f over %.1f cm (%.3f per cm) between ",
                worst.largestJump, 100.0 * worstSpacing, worstPerCm);
  out.push_back({name, "weight_jump", "warning", worstPerCm, options.maxWeightJumpPerCentimeter,
                 "probe '" + name + text + formatPoint(worst.jumpFromMeters) + " and " +
                     formatPoint(worst.jumpToMeters) + ": the lighting pops there",
                 "widen the fade between the inner and the outer range of '" + name +
                     "' (or of the volume it meets there), and let volumes overlap instead of "
                     "only touching"});
}

}  // namespace probeproxy
