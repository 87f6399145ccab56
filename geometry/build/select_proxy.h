#pragma once
// Stage 6 of the proxy build: which candidate to keep ("model no more than the scene needs").

#include "core/proxy/proxy_candidate.h"
#include "geometry/build/proxy_build_options.h"

#include <vector>

namespace probeproxy {

// Index of the candidate to keep, given candidates measured on mirror_floor:
// 1. the authored one, unless options.regenerate;
// 2. else the fewest planes (then the simpler test: infinite < cheap_k < sphere < aabb < obb <
//    convex) among those meeting the tolerance (p95 and miss rate) within the plane budget;
// 3. else, within the budget and missing at most ten times max_miss_rate, the simplest whose p95
// with misses at 180 degrees
//    (ErrorFigures::p95WithMissesDeg, what a player sees) is within 2% + 0.05 degrees of the
//    best and that misses at most max_miss_rate more than the best: so the kept proxy is never
//    worse than the aabb candidate by more than that noise;
// 4. else (none admissible) the first.
std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates,
                        const ProxyBuildOptions& options);

}  // namespace probeproxy
