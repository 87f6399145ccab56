#pragma once
// Stage 3 of the proxy build: one candidate of every kind fitted to what the probe sees, in a
// fixed order: `authored` (when the scene authors one), infinite, cheap_k, sphere (around the
// capture point), min_sphere (smallest enclosing), aabb, obb, room_box (room_box.h), hull. The
// boxes' faces move onto the walls they nearly match (geometry/tune/snap_box_to_walls.h).

#include "core/proxy/proxy_candidate.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/probe_proxies/probe_view.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace probeproxy {

struct FittedCandidates {
  std::vector<ProxyCandidate> candidates;  // errors not measured yet
  std::optional<ConvexProxy> hull;         // none when the probe sees one plane or nothing
  double hullMs = 0.0, fitMs = 0.0;
  std::vector<std::string> findings;  // why there is no hull, when there is none
};

// The hull of what the probe sees, the first and dearest fit, apart so that builds of several
// influence volumes around one capture point (layout's fit radii) make it once.
struct ViewHull {
  std::optional<ConvexProxy> hull;  // none when the probe sees one plane or nothing
  double hullMs = 0.0;
  std::optional<std::string> finding;  // why there is none
};
ViewHull fitViewHull(const ProbeView& view);

// `uprightObb`: the obb candidate stands upright (oriented_box_fit.h's uprightBoxFit) instead
// of CGAL's optimized box, for builds that fit thousands of coarse proxies.
FittedCandidates fitCandidates(const ProbeView& view, std::span<const ReflectionSample> fitSamples,
                               const std::optional<ProxyShape>& authored, bool uprightObb = false);
// With the view's hull already fitted (fitViewHull of the same view).
FittedCandidates fitCandidates(const ProbeView& view, const ViewHull& hull,
                               std::span<const ReflectionSample> fitSamples,
                               const std::optional<ProxyShape>& authored, bool uprightObb);

}  // namespace probeproxy
