#include "geometry/layout/run_layout.h"

#include "core/errors/input_error.h"
#include "core/io/memory_budget.h"
#include "geometry/layout/bands_in_sight.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/candidate_wire.h"
#include "geometry/layout/capture_sight.h"
#include "geometry/layout/grid_layout.h"
#include "geometry/layout/head_room.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/layout/leftover_floor.h"
#include "geometry/layout/near_ranges.h"
#include "geometry/layout/overlap_trim.h"
#include "geometry/layout/select_probes.h"
#include "geometry/layout/thin_ranges.h"
#include "geometry/layout/uncovered_floor_fills.h"
#include "geometry/layout/widen_fades.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/survey/floor_samples.h"
#include "geometry/survey/run_survey.h"

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>

namespace probeproxy {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Every capture point's sight, then its proxy for each fit region, smallest first; capture
// points in parallel, results in capture order whatever the thread count. `done` counts the
// capture points judged before these (progress over tiles).
std::vector<CaptureCandidates> serveCaptures(
    const LevelRayCaster& level, std::span<const LayoutCandidate> captures,
    std::span<const std::size_t> which, std::span<const FloorSample> samples,
    const LayoutOptions& o, const std::function<void(std::size_t, std::size_t)>& onDone,
    std::size_t& done) {
  std::vector<CaptureCandidates> judged(which.size());
  std::mutex progress;
  tbb::parallel_for(std::size_t{0}, which.size(), [&](std::size_t k) {
    CaptureCandidates& c = judged[k];
    c.capture = which[k];
    const glm::dvec3 capture = captures[c.capture].captureMeters;
    c.sight = captureSight(level, capture, samples, o.reachMeters);
    double farthest = 0.0;
    forEachIndex(c.sight.seen, [&](std::uint32_t s) {
      farthest = std::max(farthest, glm::distance(samples[s].sample.xMeters, capture));
    });
    const CaptureView view = seeFromCapture(level, capture, o);
    for (double fit : fitRadiiFor(farthest, o.reachMeters)) {
      c.services.push_back(serveFloor(level, view, fit, samples, c.sight.seen, o));
      c.services.back().capture = c.capture;
    }
    if (!onDone) return;
    const std::lock_guard<std::mutex> lock(progress);
    onDone(++done, captures.size());
  });
  return judged;
}

// The capture points of each tile of `tileMeters` (by the capture point's x and y), tiles in
// row order, each tile's points in capture order; one tile when tileMeters is 0.
std::vector<std::vector<std::size_t>> capturesByTile(std::span<const LayoutCandidate> captures,
                                                     double tileMeters) {
  std::map<std::pair<long long, long long>, std::vector<std::size_t>> tiles;
  for (std::size_t i = 0; i < captures.size(); ++i) {
    const glm::dvec3 at = captures[i].captureMeters;
    const auto key = tileMeters > 0.0
                         ? std::pair(static_cast<long long>(std::floor(at.y / tileMeters)),
                                     static_cast<long long>(std::floor(at.x / tileMeters)))
                         : std::pair(0LL, 0LL);
    tiles[key].push_back(i);
  }
  std::vector<std::vector<std::size_t>> inOrder;
  for (auto& [key, members] : tiles) inOrder.push_back(std::move(members));
  return inOrder;
}

struct Candidates {
  std::vector<CaptureSight> sights;        // per capture point
  std::vector<CandidateService> services;  // by capture point, then fit region
  std::size_t tiles = 0, wireBytes = 0;    // what crossed between tiles (candidate_wire.h)
};

// Every capture point judged, a tile at a time with `tileMeters`: each tile's candidates go
// through the wire as they would from another process, and come back the same. With
// `judgeTiles`, the tiles are judged wherever it sends them (a Dask cluster), all at once.
Candidates serveAll(const LevelRayCaster& level, std::span<const LayoutCandidate> captures,
                    std::span<const FloorSample> samples, const LayoutOptions& o,
                    const std::function<void(std::size_t, std::size_t)>& onDone) {
  const std::vector<std::vector<std::size_t>> tiles = capturesByTile(captures, o.tileMeters);
  std::vector<CaptureCandidates> judged(captures.size());
  Candidates c;
  const auto take = [&](const std::vector<std::size_t>& tile, std::string_view wire) {
    c.wireBytes += wire.size();
    std::vector<CaptureCandidates> part = unpackCandidates(wire);
    bool same = part.size() == tile.size();
    for (std::size_t k = 0; same && k < part.size(); ++k) same = part[k].capture == tile[k];
    if (!same)
      throw InputError("layout",
                       "a tile's candidates came back for other capture points "
                       "(was each worker given this level and these options?)");
    for (CaptureCandidates& one : part) judged[one.capture] = std::move(one);
  };
  if (o.judgeTiles) {
    const std::vector<std::string> wires = o.judgeTiles(tiles);
    if (wires.size() != tiles.size())
      throw InputError("layout", std::to_string(wires.size()) + " tiles came back of " +
                                     std::to_string(tiles.size()));
    for (std::size_t t = 0; t < tiles.size(); ++t) take(tiles[t], wires[t]);
    if (onDone) onDone(captures.size(), captures.size());
  } else {
    std::size_t done = 0;
    for (const std::vector<std::size_t>& tile : tiles) {
      std::vector<CaptureCandidates> part =
          serveCaptures(level, captures, tile, samples, o, onDone, done);
      if (o.tileMeters > 0.0)
        take(tile, packCandidates(part));
      else
        for (CaptureCandidates& one : part) judged[one.capture] = std::move(one);
    }
  }
  c.tiles = tiles.size();
  for (CaptureCandidates& one : judged) {
    c.sights.push_back(std::move(one.sight));
    for (CandidateService& s : one.services) {
      s.captureMeters = captures[one.capture].captureMeters;
      c.services.push_back(std::move(s));
    }
  }
  return c;
}

// Area share of the floor some of `which` candidates serve within the tolerance, or the kept
// probes do (per floor cell; empty without them).
double servedShare(std::span<const CandidateService> services, std::span<const std::size_t> which,
                   std::span<const FloorSample> samples, std::span<const char> keptCells) {
  std::vector<char> served(samples.size(), 0);
  if (!keptCells.empty())
    for (std::size_t i = 0; i < samples.size(); ++i) served[i] = keptCells[samples[i].cell];
  for (std::size_t c : which)
    forEachIndex(services[c].served, [&](std::uint32_t s) { served[s] = 1; });
  double area = 0.0, servedArea = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    area += samples[i].areaSquareMeters;
    if (served[i]) servedArea += samples[i].areaSquareMeters;
  }
  return area > 0.0 ? servedArea / area : 0.0;
}

// What the kept probes already do for each floor cell, as the runtime blends them (survey's
// measure): a cell is served when one of their volumes covers it and none of its samples is
// over the tolerance (a sample no kept probe can see is not held against them, as in survey).
KeptFloor keptFloor(const LevelRayCaster& level, const WalkableFloor& floor,
                    std::span<const FloorSample> samples, std::span<const SurveyProbe> kept,
                    double toleranceDeg, double& servedShare) {
  KeptFloor k;
  std::vector<InfluenceVolume> volumes;
  for (const SurveyProbe& p : kept) volumes.push_back(p.influence);
  k.covered.assign(floor.cells.size(), 0);
  tbb::parallel_for(std::size_t{0}, floor.cells.size(), [&](std::size_t c) {
    const glm::dvec3 at = floor.cells[c].pointMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters);
    k.covered[c] = std::any_of(volumes.begin(), volumes.end(),
                               [&](const InfluenceVolume& v) { return insideInfluence(v, at); });
  });
  std::vector<char> fails(samples.size(), 0);
  tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t i) {
    const SurveySampleError e =
        blendedSampleError(level, kept, volumes, samples[i].sample, BlendOptions{});
    fails[i] = e.uncovered || (!std::isnan(e.errorDeg) && e.errorDeg > toleranceDeg);
  });
  k.served = k.covered;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (fails[i]) k.served[samples[i].cell] = 0;
  double area = 0.0, served = 0.0;
  for (std::size_t c = 0; c < floor.cells.size(); ++c) {
    area += floor.cells[c].areaSquareMeters;
    if (k.served[c]) served += floor.cells[c].areaSquareMeters;
  }
  servedShare = area > 0.0 ? served / area : 0.0;
  return k;
}

// Keeps the probes not `gone`; `optional` (indices of probes) follows them.
void dropProbes(const std::set<std::size_t>& gone, std::vector<LayoutProbe>& probes,
                std::set<std::size_t>& optional) {
  if (gone.empty()) return;
  std::vector<LayoutProbe> left;
  std::set<std::size_t> optionalLeft;
  for (std::size_t p = 0; p < probes.size(); ++p) {
    if (gone.count(p)) continue;
    if (optional.count(p)) optionalLeft.insert(left.size());
    left.push_back(std::move(probes[p]));
  }
  probes = std::move(left);
  optional = std::move(optionalLeft);
}

// What judging one capture point holds until the layout is made: its sight and the served
// samples of up to three fit regions (each a subset of its sight, a bitmap no larger), three
// candidates' windows a row over the cells it sees and holds in sight (select_probes.cpp, a byte
// a cell), the in-sight cache's blocks over them (floor_in_sight.h), and its candidates'
// proxies.
std::uint64_t captureBytes(const CaptureSight& sight, std::size_t capture,
                           std::span<const FloorSample> samples, const WalkableFloor& floor,
                           const FloorInSight& inSight) {
  constexpr std::uint64_t kProxiesBytes = 16 << 10;
  constexpr int kBlockColumns = FloorInSight::kBlockColumns;
  constexpr std::uint64_t kBlockBytes = kBlockColumns * kBlockColumns;
  std::map<int, std::pair<std::size_t, std::size_t>> rows;  // row: its first and last cell held
  std::set<std::pair<int, int>> blocks;
  std::size_t last = floor.cells.size();
  forEachIndex(sight.seen, [&](std::uint32_t i) {
    const std::size_t c = samples[i].cell;
    if (c == last || !inSight.inSightOnce(capture, c)) return;
    last = c;
    const FloorCell& cell = floor.cells[c];
    const auto [it, first] = rows.emplace(cell.row, std::pair(c, c));
    if (!first) it->second.second = std::max(it->second.second, c);
    blocks.emplace(cell.row / kBlockColumns, cell.column / kBlockColumns);
  });
  std::uint64_t windowCells = 0;
  for (const auto& [row, span] : rows) windowCells += span.second - span.first + 1;
  return 4 * std::uint64_t(sight.seen.getSizeInBytes()) + 3 * windowCells +
         blocks.size() * kBlockBytes + kProxiesBytes;
}

// The floor and its samples, checked before the samples are made: a 200 m open floor once
// asked for 17 GiB and died of std::bad_alloc after a minute.
std::string floorNeeds(const WalkableFloor& floor, std::size_t captures, int samplesPerCell) {
  char needs[200];
  std::snprintf(needs, sizeof needs,
                "judging %zu capture points on the walkable floor (%.0f m^2, %zu samples)",
                captures, floor.areaSquareMeters(), floor.cells.size() * samplesPerCell);
  return needs;
}

// Then the candidate stage, from the sight of capture points spread over the level (every
// n-th): the largest stands for every capture point. What one sees is what its candidates
// hold, so an open floor seen whole asks for what the floor's every sample costs each capture
// point, and a town, where streets and walls cut each sight short, a small part of it.
void requireCandidateMemory(const LevelRayCaster& level, const WalkableFloor& floor,
                            std::span<const LayoutCandidate> captures,
                            std::span<const FloorSample> samples, const FloorInSight& inSight,
                            const LayoutOptions& o) {
  constexpr std::size_t kSpread = 16;
  const std::size_t spread = std::min(captures.size(), kSpread);
  std::vector<std::uint64_t> bytes(spread, 0);
  tbb::parallel_for(std::size_t{0}, spread, [&](std::size_t k) {
    const std::size_t capture = k * captures.size() / spread;
    const CaptureSight sight =
        captureSight(level, captures[capture].captureMeters, samples, o.reachMeters);
    bytes[k] = captureBytes(sight, capture, samples, floor, inSight);
  });
  const std::uint64_t perCapture =
      bytes.empty() ? 0 : *std::max_element(bytes.begin(), bytes.end());
  const std::uint64_t floorBytes = surveyMemoryBytes(floor.cells.size(), o.samplesPerCell);
  const std::uint64_t limit = o.maxMemoryBytes > 0 ? o.maxMemoryBytes : usableMemoryBytes();
  const std::uint64_t fit =
      limit > floorBytes && perCapture > 0 ? (limit - floorBytes) / perCapture : 0;
  requireMemory("layout", floorBytes + captures.size() * perCapture, o.maxMemoryBytes,
                floorNeeds(floor, captures.size(), o.samplesPerCell),
                fit >= 1 ? "lower --max-candidates (" + std::to_string(fit) +
                               " fit), lay the level out in parts (--seed)"
                         : "lay the level out in parts (--seed)");
}

}  // namespace

CandidateGround candidateGround(const LevelRayCaster& level, const WalkableFloor& floor,
                                const LayoutOptions& o) {
  CandidateGround g;
  g.captures =
      layoutCandidates(level, floor, o.spacingMeters, o.captureHeightMeters, o.maxCandidates);
  requireMemory("layout", surveyMemoryBytes(floor.cells.size(), o.samplesPerCell), o.maxMemoryBytes,
                floorNeeds(floor, g.captures.points.size(), o.samplesPerCell),
                "lay the level out in parts (--seed)");
  FloorSampleOptions so;
  so.samplesPerCell = o.samplesPerCell;
  so.upwardCosine = o.floor.upwardCosine;
  so.stepHeightMeters = o.floor.stepHeightMeters;
  so.seed = o.seed;
  g.samples = buildFloorSamples(level, floor, so);
  // Thousands of candidates ask for the floor they serve: one floor graph answers them all.
  g.options = o;
  g.options.candidateProxy.samples.floorGraph =
      std::make_shared<const FloorGraph>(buildFloorGraph(level, WalkableFloorOptions{}));
  return g;
}

std::string judgeCandidates(const LevelRayCaster& level, const CandidateGround& ground,
                            std::span<const std::size_t> captures) {
  for (std::size_t c : captures)
    if (c >= ground.captures.points.size())
      throw InputError("layout", "capture point " + std::to_string(c) + " of " +
                                     std::to_string(ground.captures.points.size()) +
                                     " asked for: another level or other options");
  std::size_t done = 0;
  return packCandidates(serveCaptures(level, ground.captures.points, captures, ground.samples,
                                      ground.options, {}, done));
}

namespace {

// What the candidates and the selection leave for the volumes: the chosen ranges, each with
// its candidate's capture point and fit region, and the fills. Everything else they made (the
// floor's samples, every capture point's sight and served samples, the in-sight table) is gone
// when this returns: on an open level it is most of the layout's memory, and the later stages
// need their own.
struct ChosenRanges {
  ProbeSelection selection;
  std::vector<glm::dvec3> captureMeters;  // per chosen range
  std::vector<double> fitMeters;          // per chosen range
};

ChosenRanges chooseRanges(const LevelRayCaster& level, const WalkableFloor& floor,
                          const LayoutOptions& o,
                          const std::function<void(std::size_t, std::size_t)>& onDone,
                          std::span<const SurveyProbe> kept, LayoutResult& r,
                          const std::function<void(const char*)>& lap) {
  const CandidateGround ground = candidateGround(level, floor, o);
  const std::vector<FloorSample>& samples = ground.samples;
  const std::vector<LayoutCandidate>& candidates = ground.captures.points;
  std::vector<glm::dvec3> capturePoints;
  for (const LayoutCandidate& c : candidates) capturePoints.push_back(c.captureMeters);
  const FloorInSight inSight(level, floor, capturePoints);
  requireCandidateMemory(level, floor, candidates, samples, inSight, o);
  r.floorSamples = samples.size();
  r.spacingMeters = ground.captures.spacingMeters;
  const LayoutOptions& withGraph = ground.options;
  const Candidates built = serveAll(level, candidates, samples, withGraph, onDone);
  const std::vector<CandidateService>& services = built.services;
  r.capturePoints = candidates.size();
  r.candidates = services.size();
  r.tiles = built.tiles;
  r.candidateWireBytes = built.wireBytes;
  std::vector<double> ms;
  for (const CandidateService& s : services) ms.push_back(s.buildMs);
  r.candidateMedianMs = median(ms);
  lap("candidates");

  std::vector<std::size_t> captureCells;
  for (const LayoutCandidate& c : candidates) captureCells.push_back(c.cell);
  SelectionOptions select;
  select.maxProbes = o.maxProbes;
  select.gapCells = static_cast<int>(std::lround(o.blendBandMeters / floor.spacingMeters));
  const KeptFloor keptCells =
      kept.empty() ? KeptFloor{}
                   : keptFloor(level, floor, samples, kept, o.toleranceDeg, r.keptServedShare);
  ChosenRanges chosen;
  chosen.selection = selectProbes(services, built.sights, inSight, captureCells, samples, floor,
                                  select, keptCells);
  std::vector<std::size_t> all(services.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  r.servableShare = servedShare(services, all, samples, keptCells.served);
  r.servedShare = servedShare(services, chosen.selection.chosen, samples, keptCells.served);
  for (std::size_t c : chosen.selection.chosen) {
    chosen.captureMeters.push_back(services[c].captureMeters);
    chosen.fitMeters.push_back(services[c].fitMeters);
  }
  lap("selection");
  return chosen;
}

void layoutByCandidates(const LevelRayCaster& level, std::span<const glm::dvec3> seedsMeters,
                        const WalkableFloor& floor, const LayoutOptions& o,
                        const std::function<void(std::size_t, std::size_t)>& onDone,
                        std::span<const SurveyProbe> kept, LayoutResult& r) {
  auto lapStart = std::chrono::steady_clock::now();
  const auto lap = [&](const char* stage) {
    const auto now = std::chrono::steady_clock::now();
    r.stageSeconds.emplace_back(stage, std::chrono::duration<double>(now - lapStart).count());
    if (o.onStageDone) o.onStageDone(stage, r.stageSeconds.back().second);
    lapStart = now;
  };
  const ChosenRanges ranges = chooseRanges(level, floor, o, onDone, kept, r, lap);
  const ProbeSelection& selection = ranges.selection;
  // Each probe's box, ranges in the order the cover took them, then the fills, each kept clear
  // of the inner ranges before it (keepClearOfInnerRanges): windows of neighbouring heights
  // (a ledge over a lower floor) put one range's box in the air over the other's floor.
  std::vector<InfluenceVolume> volumes;
  for (const SurveyProbe& k : kept) volumes.push_back(k.influence);
  const std::vector<InfluenceVolume> keptVolumes = volumes;  // never cut, trimmed or moved
  // The survey walks a finer floor than the candidates (validate's leak rule too).
  const WalkableFloor walked = walkableFloor(level, seedsMeters, o.coverFloor);
  // A probe whose capture point the cut under a range above brings down into a surface, with
  // no clear height left over its floor, is not made: its floor is left to the uncovered
  // floor's fills.
  const auto add = [&](const FloorRect& rect, glm::dvec3 capture, double fitMeters) {
    glm::dvec3 lo, hi;
    floorRectBounds(floor, rect, capture, lo, hi);
    const glm::dvec3 chosen = capture;
    keepClearOfInnerRanges(lo, hi, capture, rect.floorMeters, volumes, o.blendBandMeters,
                           StripForHeadRoom::atMostAQuarter);
    if (!clearMovedCapture(level, chosen, capture, rect.floorMeters, hi.z)) return;
    pullBandsIntoSight(level, walked, capture, o.blendBandMeters, lo, hi);
    r.probes.push_back({capture, influenceOfBounds(lo, hi, o.blendBandMeters), fitMeters});
    volumes.push_back(r.probes.back().influence);
  };
  for (std::size_t p = 0; p < selection.chosen.size(); ++p)
    add(selection.ranges[p], ranges.captureMeters[p], ranges.fitMeters[p]);
  // --max-probes is a cap on every probe the layout makes, fills too: floor the cover's probes
  // leave is then left uncovered, and the survey says how much.
  const auto full = [&] { return o.maxProbes > 0 && r.probes.size() >= o.maxProbes; };
  const FloorColumns columns(floor);
  for (const FloorRect& fill : selection.fills) {
    if (full()) break;
    std::vector<std::size_t> cells;
    columns.forEachIn(fill, [&](std::size_t cell) { cells.push_back(cell); });
    const glm::dvec3 middle = floor.cells[middleCell(columns, fill)].pointMeters;
    const ClearCapture clear = clearCaptureAbove(
        level, floor, nearestFirst(floor, std::move(cells), middle), o.captureHeightMeters);
    // A scene may not hold a probe in a surface: its floor is left to the uncovered floor's
    // fills.
    if (clear.clearanceMeters < kMinCaptureClearanceMeters) continue;
    add(fill, clear.captureMeters, kRoomFitMeters);
  }
  // Strips narrower than the gap join a neighbour (five bands met over the gap beside them).
  joinThinRanges(level, walked, o.blendBandMeters, keptVolumes, r.probes);
  // Cameras over a ramp's or a ledge's floor stand over its range's top (head_room.h); the
  // fills' ranges too, once they are made.
  raiseRangesOverRaisedFloor(walked, o.blendBandMeters, keptVolumes, r.probes);
  volumes.resize(kept.size());
  for (const LayoutProbe& p : r.probes) volumes.push_back(p.influence);
  lap("volumes");
  // What of the survey's floor no volume reaches, or only the far ends of bands reach.
  std::set<std::size_t> optional;  // of r.probes
  for (const FloorFill& f :
       fillsForUncoveredFloor(level, walked, volumes, o.blendBandMeters, o.captureHeightMeters)) {
    if (full()) break;
    if (f.optional) optional.insert(r.probes.size());
    r.probes.push_back({f.captureMeters, f.influence, kRoomFitMeters});
  }
  raiseRangesOverRaisedFloor(walked, o.blendBandMeters, keptVolumes, r.probes);
  // Ranges a capture point held too near their neighbours for a smooth blend part
  // (near_ranges.h).
  partNearRanges(o.blendBandMeters, keptVolumes, r.probes);
  // Floor no fill could take joins the volume that reaches it for the least growth.
  coverLeftoverFloor(level, walked, o.blendBandMeters, keptVolumes, r.probes);
  lap("uncovered_floor");
  // Where more bands cross than the blend takes (overlap_trim.h), to validate's defaults. An
  // optional fill in a crowd the trim could not free, its faces moved or not, goes, and the rest
  // rise and are trimmed again without it: until no such fill is left in a crowd (downer: a
  // second fill in the crowd the first one's going left).
  std::vector<LayoutProbe> untrimmed = r.probes;
  for (;;) {
    std::set<std::size_t> dropped;
    for (const OverlapPoint& p : trimBandsOverOverlapLimit(
             level, walked, o.blendBandMeters, ValidateOptions{}, keptVolumes, r.probes, optional))
      for (int v : p.volumes)
        if (static_cast<std::size_t>(v) >= kept.size() && optional.count(v - kept.size()))
          dropped.insert(v - kept.size());
    if (dropped.empty()) break;
    r.probes = std::move(untrimmed);
    dropProbes(dropped, r.probes, optional);
    raiseRangesOverRaisedFloor(walked, o.blendBandMeters, keptVolumes, r.probes);
    untrimmed = r.probes;
  }
  lap("overlap_trim");
  // Where the blend still pops, a fade widens (widen_fades.h).
  widenFadesWhereWeightsJump(level, walked, o.blendBandMeters, ValidateOptions{}, keptVolumes,
                             r.probes);
  lap("fades");
}

}  // namespace

LayoutResult runLayout(const LevelRayCaster& level, std::span<const glm::dvec3> seedsMeters,
                       const LayoutOptions& o,
                       const std::function<void(std::size_t, std::size_t)>& onCandidateDone,
                       std::span<const SurveyProbe> kept) {
  const auto start = std::chrono::steady_clock::now();
  o.check();
  LayoutResult r;
  r.spacingMeters = o.spacingMeters;
  if (o.baseline == LayoutBaseline::Spawn) {
    const double spawnRadius = o.reachMeters > 0.0 ? o.reachMeters : kSpawnSphereMeters;
    for (const glm::dvec3& seed : seedsMeters)
      r.probes.push_back({seed, SphereInfluence{seed, spawnRadius, spawnRadius}});
  } else {
    const WalkableFloor floor = walkableFloor(level, seedsMeters, o.floor);
    if (floor.cells.empty())
      throw InputError("layout", "no walkable floor under any of the " +
                                     std::to_string(seedsMeters.size()) +
                                     " seed points (spawn or capture points)");
    r.floorCells = floor.cells.size();
    if (o.baseline == LayoutBaseline::Grid) {
      for (const GridCellProbe& g : gridLayoutWithin(
               level, floor, o.spacingMeters, o.captureHeightMeters, o.maxProbes, r.spacingMeters))
        r.probes.push_back({g.captureMeters, influenceAroundFloor(floor, g.cells, g.captureMeters,
                                                                  o.blendBandMeters)});
    } else {
      layoutByCandidates(level, seedsMeters, floor, o, onCandidateDone, kept, r);
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace probeproxy
