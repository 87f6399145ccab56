#pragma once
// `layout`: probes for a whole level (docs/layout.md). The walkable floor a player reaches from
// the seed points is sampled as `survey` samples it (coarser); capture-point candidates are
// spread over it (layout_candidates.h), each one's proxy built and its error measured on the
// floor within reach (candidate_service.h, all cores); the fewest that serve the floor within
// the tolerance are chosen (select_probes.h), and each gets an influence box around the floor
// it shades best (layout_influence.h). The baselines place probes without measuring: a grid
// (grid_layout.h) or the seed (spawn) points with spheres. Deterministic, whatever the thread
// count.

#include "core/scene/influence_volume.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_options.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/blended_error.h"
#include "geometry/survey/floor_samples.h"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace probeproxy {

// The spawn baseline's spheres when the layout has no reach.
inline constexpr double kSpawnSphereMeters = 10.0;

struct LayoutProbe {
  glm::dvec3 captureMeters{0.0};
  InfluenceVolume influence;
  double fitMeters = 0.0;  // its proxy is fitted to the floor connected to it within this radius
};

struct LayoutResult {
  std::vector<LayoutProbe> probes;
  std::size_t floorCells = 0, floorSamples = 0;
  std::size_t capturePoints = 0;  // candidate capture points (0 for the baselines)
  std::size_t candidates = 0;     // proxies built and measured, a few per capture point
  double candidateMedianMs = std::numeric_limits<double>::quiet_NaN();  // one candidate's cost
  // Tiles the candidate stage took (LayoutOptions::tileMeters), and the bytes their candidates
  // crossed in (candidate_wire.h; 0 in one tile).
  std::size_t tiles = 0, candidateWireBytes = 0;
  // Floor (area share) some chosen probe serves within the tolerance on its own, and that some
  // candidate could: what the selection reached of what it could reach.
  double servedShare = 0.0, servableShare = 0.0;
  double spacingMeters = 0.0;  // the candidates' grid, or the grid baseline's spacing taken
  // With kept probes: the floor (area share) they serve within the tolerance before anything is
  // added.
  double keptServedShare = 0.0;
  double seconds = 0.0;
  // Where the seconds went, stage by stage in the order they ran (candidates, selection,
  // volumes, uncovered_floor, overlap_trim, fades): on a large level one stage can take most.
  std::vector<std::pair<std::string, double>> stageSeconds;
};

// The candidate stage's ground, as layout makes it from the level's walkable floor (the coarse
// one, LayoutOptions::floor): the capture points, the floor samples they are judged on, and
// the options with the level's floor graph. The same on every process for the same level,
// floor and options, so a capture point's index names it anywhere. Throws InputError when it
// would not fit LayoutOptions::maxMemoryBytes.
struct CandidateGround {
  LayoutCandidates captures;
  std::vector<FloorSample> samples;
  LayoutOptions options;
};
CandidateGround candidateGround(const LevelRayCaster& level, const WalkableFloor& floor,
                                const LayoutOptions& options);

// The candidates of `captures` (indices into ground.captures.points) judged here, packed for
// the process that selects (candidate_wire.h): what a tile or a Dask task returns.
std::string judgeCandidates(const LevelRayCaster& level, const CandidateGround& ground,
                            std::span<const std::size_t> captures);

// `onCandidateDone(done, total)` reports candidate builds (serialized), the slow part.
// `kept`: probes that stay as they are (an artist's, with their proxies): the layout adds only
// probes for the floor they do not serve within the tolerance; result.probes are the added ones.
// Throws InputError when no seed stands over walkable floor.
LayoutResult runLayout(const LevelRayCaster& level, std::span<const glm::dvec3> seedsMeters,
                       const LayoutOptions& options,
                       const std::function<void(std::size_t, std::size_t)>& onCandidateDone = {},
                       std::span<const SurveyProbe> kept = {});

}  // namespace probeproxy
