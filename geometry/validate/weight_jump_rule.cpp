// weight_jump: a blend weight that changes abruptly between neighbouring points pops as the
// camera moves (Lagarde's weights, core/blend). Measured on a horizontal grid at each capture
// height, where a camera can be (camera_space.h), and scaled to a change per centimetre so the
// grid spacing does not move the limit.

#include "core/blend/weight_continuity.h"
#include "geometry/validate/camera_space.h"
#include "geometry/validate/validation_rules.h"

#include <cmath>
#include <cstdio>
#include <set>

namespace probeproxy {

void checkWeightJumps(const Scene& scene, const LevelRayCaster& level, const WalkableFloor& walked,
                      const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (scene.probes.empty()) return;
  std::vector<InfluenceVolume> volumes;
  std::set<double> heights;
  for (const Probe& p : scene.probes) {
    volumes.push_back(p.influence);
    heights.insert(p.captureMeters.z);
  }
  const ReachableMask cameras = [&](std::span<const glm::dvec3> points, std::span<char> reachable) {
    markCameraSpace(level, walked, options.cameraHeadRoomMeters, points, reachable);
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
    const WeightContinuity c = measureWeightContinuity(volumes, grid, {}, cameras);
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
