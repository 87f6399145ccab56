#include "geometry/layout/leftover_floor.h"

#include "core/scene/influence_volume.h"
#include "geometry/engines/engine_model.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <limits>
#include <optional>

namespace probeproxy {

namespace {

// Over the grown face, so that rounding never leaves the point on it.
constexpr double kGrowthMarginMeters = 0.001;

bool inAnyVolume(std::span<const InfluenceVolume> kept, const std::vector<LayoutProbe>& probes,
                 glm::dvec3 p) {
  return std::any_of(kept.begin(), kept.end(),
                     [&](const InfluenceVolume& v) { return insideInfluence(v, p); }) ||
         std::any_of(probes.begin(), probes.end(),
                     [&](const LayoutProbe& q) { return insideInfluence(q.influence, p); });
}

bool captureSees(const LevelRayCaster& level, glm::dvec3 capture, glm::dvec3 p) {
  const glm::dvec3 to = p - capture;
  const double length = glm::length(to);
  if (length <= 0.0) return true;
  Ray ray;
  ray.originMeters = capture;
  ray.direction = glm::vec3(to / length);
  ray.tMax = static_cast<float>(length);
  return !level.firstHit(ray).hit();
}

// How far past each face of the box the cell's square reaches at `p`'s height (0 on axes it is
// within): the survey's samples of a cell lie anywhere in its square.
glm::dvec3 growthToHold(const BoxInfluence& box, glm::dvec3 p, double halfCellMeters) {
  const glm::dvec3 reach =
      glm::abs(p - box.centerMeters) + glm::dvec3(halfCellMeters, halfCellMeters, 0.0);
  return glm::max(reach - box.halfExtentsMeters, glm::dvec3(0.0));
}

}  // namespace

std::vector<std::size_t> coverLeftoverFloor(const LevelRayCaster& level,
                                            const WalkableFloor& walked, double gapMeters,
                                            std::span<const InfluenceVolume> kept,
                                            std::vector<LayoutProbe>& probes) {
  // Growth is held to a gap past each box as it came, not as earlier cells grew it: a strip
  // wider than that is not one band's to take.
  std::vector<glm::dvec3> mostHalf;
  for (const LayoutProbe& q : probes)
    if (const BoxInfluence* box = std::get_if<BoxInfluence>(&q.influence))
      mostHalf.push_back(box->halfExtentsMeters + glm::dvec3(gapMeters));
    else
      mostHalf.push_back(glm::dvec3(0.0));
  std::vector<std::size_t> left;
  for (std::size_t c = 0; c < walked.cells.size(); ++c) {
    const glm::dvec3 p = walked.cells[c].pointMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters);
    if (inAnyVolume(kept, probes, p)) continue;
    std::optional<std::size_t> best;
    glm::dvec3 bestGrowth(0.0);
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < probes.size(); ++i) {
      const BoxInfluence* box = std::get_if<BoxInfluence>(&probes[i].influence);
      if (!box || box->worldFromBox != glm::dquat(1.0, 0.0, 0.0, 0.0)) continue;
      const glm::dvec3 growth = growthToHold(*box, p, 0.5 * walked.spacingMeters);
      const double most = std::max({growth.x, growth.y, growth.z});
      if (glm::any(glm::greaterThan(box->halfExtentsMeters + growth, mostHalf[i])) || most >= least)
        continue;
      if (!captureSees(level, probes[i].captureMeters, p)) continue;
      best = i, least = most, bestGrowth = growth;
    }
    if (!best) {
      left.push_back(c);
      continue;
    }
    BoxInfluence& box = std::get<BoxInfluence>(probes[*best].influence);
    for (int a = 0; a < 3; ++a)
      if (bestGrowth[a] > 0.0) box.halfExtentsMeters[a] += bestGrowth[a] + kGrowthMarginMeters;
  }
  return left;
}

}  // namespace probeproxy
