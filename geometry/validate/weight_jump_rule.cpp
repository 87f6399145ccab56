// weight_jump: a blend weight that changes abruptly between neighbouring points pops as the
// camera moves (Lagarde's weights, core/blend). Measured on a horizontal grid at the capture
// heights (at most one a band of height, camera_planes.h), where a camera can be
// (camera_space.h), and scaled to a change per centimetre so the grid spacing does not move the
// limit.

#include "core/blend/weight_continuity.h"
#include "geometry/validate/camera_planes.h"
#include "geometry/validate/camera_space.h"
#include "geometry/validate/validation_rules.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace probeproxy {

void checkWeightJumps(const Scene& scene, const LevelRayCaster& level, const WalkableFloor& walked,
                      const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (scene.probes.empty()) return;
  std::vector<InfluenceVolume> volumes;
  std::vector<double> captureHeights;
  for (const Probe& p : scene.probes) {
    volumes.push_back(p.influence);
    captureHeights.push_back(p.captureMeters.z);
  }
  const ReachableMask cameras = [&](std::span<const glm::dvec3> points, std::span<char> reachable) {
    markCameraSpace(level, walked, options.cameraHeadRoomMeters, points, reachable);
  };
  // Each height on its own (a laid-out map has dozens), the worst taken in height order.
  const std::vector<double> zs = cameraPlaneHeights(captureHeights);
  std::vector<WeightContinuity> found(zs.size());
  std::vector<double> spacing(zs.size());
  tbb::parallel_for(std::size_t{0}, zs.size(), [&](std::size_t h) {
    WeightGrid grid = gridOverVolumes(volumes, zs[h], options.weightGridMeters);
    const glm::dvec2 size = grid.maxMeters - grid.minMeters;
    const double points = (size.x / grid.spacingMeters + 1) * (size.y / grid.spacingMeters + 1);
    const double budget = static_cast<double>(options.gridPointBudget);
    if (points > budget)
      grid = gridOverVolumes(volumes, zs[h], options.weightGridMeters * std::sqrt(points / budget));
    found[h] = measureWeightContinuity(volumes, grid, {}, cameras);
    spacing[h] = grid.spacingMeters;
  });
  WeightContinuity worst;
  double worstPerCm = 0.0, worstSpacing = 0.0;
  for (std::size_t h = 0; h < zs.size(); ++h) {
    const double perCm = found[h].largestJump / (100.0 * spacing[h]);
    if (perCm > worstPerCm) worstPerCm = perCm, worst = found[h], worstSpacing = spacing[h];
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
