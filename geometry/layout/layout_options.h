#pragma once
// What `layout` may do and what it must reach (docs/layout.md): the tolerance each floor
// sample is served within, how candidates are spread and built, and how the chosen probes'
// influence volumes blend. Plain data; check() throws InputError for a value out of range.

#include "geometry/floor/walkable_floor.h"
#include "geometry/probe_proxies/proxy_build_options.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

enum class LayoutBaseline {
  None,   // the layout itself: the fewest probes that serve the floor within the tolerance
  Grid,   // a probe every `spacingMeters` over the walkable floor, box cells, aabb proxies
  Spawn,  // a probe at every spawn point, a sphere of `reachMeters` (or 10 m), auto proxies
};

inline constexpr double kMaxBlendBandMeters = 50.0;

struct LayoutOptions {
  LayoutBaseline baseline = LayoutBaseline::None;
  double toleranceDeg = 5.0;  // a floor sample is served where one probe's error is this or less
  std::size_t maxProbes = 0;  // 0: as many as the floor needs; else at most this many
  // Keep the scene's probes as authored and add probes only for the floor they do not serve
  // within the tolerance (the layout itself only, not a baseline).
  bool keepAuthored = false;
  double spacingMeters = 2.0;  // the candidates' grid (and the grid baseline's)
  // At most this many capture points: on a level whose floor holds more at `spacingMeters`,
  // the candidates' grid is coarsened until it fits (layout time grows with the count).
  std::size_t maxCandidates = 800;
  // A candidate is fitted to, and serves, floor samples within this distance of its capture
  // point; 0: all the floor it sees (a hangar keeps one probe).
  double reachMeters = 0.0;
  // Above the floor; at most half the free height above it. A mirror floor's reflection rays
  // all come from the eye's image under the floor, so a capture point low over the floor lies
  // nearer them and sees each true hit from nearer the ray's own direction: on four tuning maps
  // 0.6 m left 3-4 points less floor over the tolerance than 1.6 m (eye height), less occluded,
  // and the p95 3-9 deg lower; 0.45 and 0.8 m did better on one map of the four at most
  // (docs/layout.md, "The capture height"). The grid baseline takes it too.
  double captureHeightMeters = 0.6;
  // Neighbours' inner ranges stand this far apart; each outer range reaches
  // kOuterBandOverGap times as far past its inner one (layout_influence.h).
  double blendBandMeters = 1.0;
  // How finely candidates are judged: a coarser floor and fewer samples than `survey` takes.
  WalkableFloorOptions floor{0.5};
  // The floor every point of which must lie in some volume: the survey's.
  WalkableFloorOptions coverFloor;
  // A candidate's share of a cell's samples decides its range (select_probes.h): with 2, a
  // cell one serves at 80% showed as half served as often as not (warfare, one pass at 0.8: p95
  // 32.3 degrees against 35.6 with 2 samples, the layout 10% slower).
  int samplesPerCell = 4;
  std::uint32_t seed = 1;
  // Each candidate's proxy: a small depth cube and few samples (a few thousand candidates per
  // level); the chosen probes are built again with `finalProxy`.
  ProxyBuildOptions candidateProxy = coarseCandidateProxyOptions();
  // The candidate stage judges the capture points a square tile of the floor this wide at a
  // time, each tile's candidates crossing the wire (candidate_wire.h) as from another process:
  // the same layout, bytes for bytes. 0: all at once.
  double tileMeters = 0.0;
  // Where the tiles are judged when not here: given each tile's capture points (indices into
  // the candidate ground's, run_layout.h), returns each tile's judgeCandidates bytes, in order
  // (scripts/layout_dask.py sends them to a Dask cluster). Empty: here, a tile at a time.
  std::function<std::vector<std::string>(const std::vector<std::vector<std::size_t>>&)> judgeTiles;
  // Told as each stage ends (the names of LayoutResult::stageSeconds): on an open level a layout
  // runs for an hour, and its front end says where it is. May be empty.
  std::function<void(std::string_view stage, double seconds)> onStageDone;
  // What the candidate stage may take (core/io/memory_budget.h); 0: what the process can use.
  std::uint64_t maxMemoryBytes = 0;
  ProxyBuildOptions finalProxy;

  static ProxyBuildOptions coarseCandidateProxyOptions();
  void check() const;
};

}  // namespace probeproxy
