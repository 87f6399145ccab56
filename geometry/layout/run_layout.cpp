#include "geometry/layout/run_layout.h"

#include "core/errors/input_error.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/grid_layout.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/layout/select_probes.h"
#include "geometry/survey/floor_samples.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

namespace probeproxy {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::vector<CandidateService> serveAll(
    const LevelRayCaster& level, const std::vector<LayoutCandidate>& candidates,
    std::span<const FloorSample> samples, const LayoutOptions& o,
    const std::function<void(std::size_t, std::size_t)>& onDone) {
  // Each capture point with each fit region, smallest first.
  const std::size_t fits = kLayoutFitFractions.size();
  std::vector<CandidateService> services(candidates.size() * fits);
  std::mutex progress;
  std::size_t done = 0;
  tbb::parallel_for(std::size_t{0}, services.size(), [&](std::size_t i) {
    services[i] = serveFloor(level, candidates[i / fits].captureMeters,
                             kLayoutFitFractions[i % fits] * o.reachMeters, samples, o);
    if (!onDone) return;
    const std::lock_guard<std::mutex> lock(progress);
    onDone(++done, services.size());
  });
  return services;
}

// Area shares of the floor served within the tolerance by any of `which` services.
double servedShare(std::span<const CandidateService> services, std::span<const std::size_t> which,
                   std::span<const FloorSample> samples, double toleranceDeg) {
  std::vector<char> served(samples.size(), 0);
  for (std::size_t c : which)
    for (std::size_t k = 0; k < services[c].samples.size(); ++k)
      if (services[c].errorDeg[k] <= toleranceDeg) served[services[c].samples[k]] = 1;
  double area = 0.0, servedArea = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    area += samples[i].areaSquareMeters;
    if (served[i]) servedArea += samples[i].areaSquareMeters;
  }
  return area > 0.0 ? servedArea / area : 0.0;
}

void layoutByCandidates(const LevelRayCaster& level, const WalkableFloor& floor,
                        const LayoutOptions& o,
                        const std::function<void(std::size_t, std::size_t)>& onDone,
                        LayoutResult& r) {
  FloorSampleOptions so;
  so.samplesPerCell = o.samplesPerCell;
  so.upwardCosine = o.floor.upwardCosine;
  so.stepHeightMeters = o.floor.stepHeightMeters;
  so.seed = o.seed;
  const std::vector<FloorSample> samples = buildFloorSamples(level, floor, so);
  r.floorSamples = samples.size();

  const std::vector<LayoutCandidate> candidates =
      layoutCandidates(level, floor, o.spacingMeters, o.captureHeightMeters);
  const std::vector<CandidateService> services = serveAll(level, candidates, samples, o, onDone);
  r.candidates = services.size();
  std::vector<double> ms;
  for (const CandidateService& s : services) ms.push_back(s.buildMs);
  r.candidateMedianMs = median(ms);

  const ProbeSelection selection = selectProbes(services, samples, o.toleranceDeg, o.maxProbes);
  std::vector<std::size_t> all(services.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  r.servableShare = servedShare(services, all, samples, o.toleranceDeg);
  r.servedShare = servedShare(services, selection.chosen, samples, o.toleranceDeg);

  std::vector<std::vector<std::size_t>> ownedCells(selection.chosen.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!selection.chosen.empty()) ownedCells[selection.owner[i]].push_back(samples[i].cell);
  for (std::size_t p = 0; p < selection.chosen.size(); ++p) {
    const CandidateService& chosen = services[selection.chosen[p]];
    std::vector<std::size_t>& cells = ownedCells[p];
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    if (cells.empty()) cells.push_back(candidates[selection.chosen[p] / kLayoutFitFractions.size()].cell);
    r.probes.push_back({chosen.captureMeters,
                        influenceAroundFloor(floor, cells, chosen.captureMeters, o.blendBandMeters),
                        chosen.fitMeters});
  }
}

}  // namespace

LayoutResult runLayout(const LevelRayCaster& level, std::span<const glm::dvec3> seedsMeters,
                       const LayoutOptions& o,
                       const std::function<void(std::size_t, std::size_t)>& onCandidateDone) {
  const auto start = std::chrono::steady_clock::now();
  o.check();
  LayoutResult r;
  r.spacingMeters = o.spacingMeters;
  if (o.baseline == LayoutBaseline::Spawn) {
    for (const glm::dvec3& seed : seedsMeters)
      r.probes.push_back({seed, SphereInfluence{seed, o.reachMeters, o.reachMeters}});
  } else {
    const WalkableFloor floor = walkableFloor(level, seedsMeters, o.floor);
    if (floor.cells.empty())
      throw InputError("layout", "no walkable floor under any of the " +
                                     std::to_string(seedsMeters.size()) +
                                     " seed points (spawn or capture points)");
    r.floorCells = floor.cells.size();
    if (o.baseline == LayoutBaseline::Grid) {
      for (const GridCellProbe& g : gridLayoutWithin(level, floor, o.spacingMeters,
                                                     o.captureHeightMeters, o.maxProbes,
                                                     r.spacingMeters))
        r.probes.push_back({g.captureMeters, influenceAroundFloor(floor, g.cells, g.captureMeters,
                                                                  o.blendBandMeters)});
    } else {
      layoutByCandidates(level, floor, o, onCandidateDone, r);
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace probeproxy
