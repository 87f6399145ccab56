#pragma once
// Stage 6 of the proxy build: which candidate to keep ("model no more than the scene needs").

#include "core/proxy/proxy_candidate.h"
#include "geometry/probe_proxies/proxy_build_options.h"

#include <vector>

namespace probeproxy {

// Index of the candidate to keep, given candidates measured on mirror_floor:
// 1. the authored one, unless options.regenerate;
// 2. else the fewest planes (then the simpler test: infinite < cheap_k < sphere < aabb < obb <
//    convex) among those meeting the tolerance (p95 and miss rate) within the plane budget;
// 3. else, among those within the budget that miss at most ten times max_miss_rate and whose
//    p95 with misses at 180 degrees (ErrorFigures::p95WithMissesDeg) is no worse than the
//    aabb candidate's (what an engine's box projection uses) by more than 2% + 0.05 degrees,
//    the simplest within 5% + 0.01 degrees of the lowest mean error (misses at 180 degrees):
//    so the kept proxy is never worse than the box on either figure a player sees;
// 4. else (none admissible) the first.
std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates,
                        const ProxyBuildOptions& options);

// When the kept candidate does not meet the tolerance: what was kept, the candidate nearest to
// meeting it and why it was refused, and what would help, e.g. "kept cheap_k at p95 47.03 deg,
// over the 0.25 deg tolerance: no candidate meets both (the nearest, room_box at p95 11.30 deg,
// misses 7.0% of the samples, over the 0.1% allowed; --max-miss-rate); where one probe serves
// more than one room, a second probe (validate's split_probe), or `layout --keep-authored`,
// would meet it". Empty when the kept one meets it, or is the authored proxy kept as authored.
std::string overToleranceFinding(const std::vector<ProxyCandidate>& candidates, std::size_t kept,
                                 const ProxyBuildOptions& options);

}  // namespace probeproxy
