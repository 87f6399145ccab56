#pragma once
// Which candidates become probes (README "Layout"): the fewest that serve every floor sample
// within the tolerance some candidate can serve it in, by greedy cover of floor area (each
// step takes the candidate that serves the most floor not yet served; ties to the lower
// index). Floor no candidate serves within the tolerance still gets the candidates that see
// it most, the same way, so every sample some candidate sees is seen by a probe. A refining
// pass then drops every probe whose floor the others serve and see as well. With `maxProbes`,
// the cover stops at that many. Deterministic.

#include "geometry/layout/candidate_service.h"

#include <cstddef>
#include <span>
#include <vector>

namespace probeproxy {

struct ProbeSelection {
  std::vector<std::size_t> chosen;  // candidate indices, in the order they were taken
  // Per floor sample, the index into `chosen` of the probe whose region it is: whole floor
  // cells, each to the probe that serves most of its samples within the tolerance, then sees
  // most, then stands nearest.
  std::vector<std::size_t> owner;
};

ProbeSelection selectProbes(std::span<const CandidateService> services,
                            std::span<const FloorSample> samples, double toleranceDeg,
                            std::size_t maxProbes);

}  // namespace probeproxy
