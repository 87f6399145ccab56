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
// 3. else the most accurate within the budget by mean error (misses at 180 degrees), sparing
//    the planes that buy less than 5% of it: a concave room that no convex proxy models gets a
//    simple proxy, not 30 planes for a hundredth of a degree;
// 4. else (nothing but misses) the first.
std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates,
                        const ProxyBuildOptions& options);

}  // namespace probeproxy
