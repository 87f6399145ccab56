#pragma once
// How continuous the blend weights are over a horizontal grid: the largest change of any
// probe's weight between two neighbouring grid points that are both covered, and how far the
// weights' sum strays from 1 at covered points. Crossing the edge of the covered region is not
// a jump (outside, no probe applies), but a single uncovered point between two covered ones
// is (volumes that only touch: the point of interest crosses the gap at once), so those two
// are compared. An optional mask limits the grid to where the point of interest can be (e.g.
// above a floor of the level): influence volumes reach into walls, where nobody stands.
// Used by the tests' continuity check and by validation ("a weight that jumps between
// neighbouring points").

#include "core/blend/blend_weights.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <span>

namespace probeproxy {

struct WeightGrid {
  glm::dvec2 minMeters{0.0};  // world x, y of the first grid point
  glm::dvec2 maxMeters{0.0};  // the grid stops at the last point <= this
  double zMeters = 0.0;       // height of the plane
  double spacingMeters = 0.01;
};

struct WeightContinuity {
  double largestJump = 0.0;  // max |w_i(p) - w_i(q)| over neighbours p, q both covered
  int jumpProbe = -1;        // the probe whose weight jumps most (-1: no covered neighbours)
  glm::dvec3 jumpFromMeters{0.0}, jumpToMeters{0.0};
  double largestSumError = 0.0;  // max |sum_i w_i - 1| over covered points
  long long coveredPoints = 0;
  long long points = 0;
};

// Fills reachable[i] (0 or 1) for each point of one grid row.
using ReachableMask =
    std::function<void(std::span<const glm::dvec3> pointsMeters, std::span<char> reachable)>;

// Without a mask every grid point counts. Throws std::invalid_argument on a spacing <= 0 or an
// empty box.
WeightContinuity measureWeightContinuity(std::span<const InfluenceVolume> volumes,
                                         const WeightGrid& grid, const BlendOptions& options = {},
                                         const ReachableMask& reachable = {});

// The grid over the union of the volumes' outer bounds (core/scene/influence_volume.h), at z,
// on cell centres (half a spacing in from whole multiples of it).
WeightGrid gridOverVolumes(std::span<const InfluenceVolume> volumes, double zMeters,
                           double spacingMeters);

}  // namespace probeproxy
