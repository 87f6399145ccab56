// split_probe: a probe whose floor no proxy of its own brings under the tolerance, where a
// second probe would. Capture points are tried over the probe's walkable floor, each
// with a proxy fitted as layout fits its candidates'; each square metre of floor goes to the
// probe that serves it better, and the point whose split leaves the lowest p95 is named if that
// p95 is within the tolerance.

#include "core/measures/error_figures.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/layout_candidates.h"
#include "geometry/layout/layout_options.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/probe_proxies/fit_candidates.h"
#include "geometry/probe_proxies/probe_view.h"
#include "geometry/survey/blended_error.h"
#include "geometry/validate/validation_rules.h"

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

namespace probeproxy {

namespace {

constexpr double kTrySpacingMeters = 1.5;  // between the capture points tried
constexpr std::size_t kMaxTries = 64;
constexpr double kSplitCellMeters = 1.0;  // the squares of floor the split hands out
// The widest fit region tried: past any room the validator's probes span, "all it sees".
constexpr double kAllItSeesFitMeters = 4.0 * kRoomsFitMeters;

// Floor points of the probe's volume, one per kTrySpacingMeters square and storey, at most
// kMaxTries (every k-th when there are more), in floor order.
std::vector<glm::dvec3> capturesToTry(const LevelRayCaster& level, const Probe& probe,
                                      const std::vector<FloorCell>& floor) {
  // The floor point nearest each square's centre (away from the walls the square touches).
  std::map<std::tuple<long, long, long>, std::pair<double, glm::dvec3>> squares;
  for (const FloorCell& f : floor) {
    const glm::dvec3 p = f.pointMeters;
    if (!insideInfluence(probe.influence, p + glm::dvec3(0.0, 0.0, kBlendLiftMeters))) continue;
    const double column = std::floor(p.x / kTrySpacingMeters),
                 row = std::floor(p.y / kTrySpacingMeters);
    const double offCentre =
        std::hypot(p.x - (column + 0.5) * kTrySpacingMeters, p.y - (row + 0.5) * kTrySpacingMeters);
    const auto key =
        std::make_tuple(std::lround(row), std::lround(column), std::lround(std::floor(p.z / 2.0)));
    const auto [at, fresh] = squares.emplace(key, std::pair{offCentre, p});
    if (!fresh && offCentre < at->second.first) at->second = {offCentre, p};
  }
  // Where `layout` would capture a probe over that floor.
  const double height = LayoutOptions{}.captureHeightMeters;
  std::vector<glm::dvec3> captures;
  for (const auto& [key, nearest] : squares) {
    const glm::dvec3 capture = captureAbove(level, nearest.second, height);
    if (!insideInfluence(probe.influence, capture)) continue;
    if (nearestSurface(level, capture).distanceMeters < kLayoutCaptureClearanceMeters) continue;
    captures.push_back(capture);
  }
  if (captures.size() > kMaxTries) {
    std::vector<glm::dvec3> every;
    const double step = double(captures.size()) / double(kMaxTries);
    for (std::size_t k = 0; k < kMaxTries; ++k)
      every.push_back(captures[static_cast<std::size_t>(k * step)]);
    captures = std::move(every);
  }
  return captures;
}

// The floor cut into kSplitCellMeters squares (per storey): each sample's square, in 0..count.
std::vector<std::size_t> splitSquares(std::span<const ReflectionSample> samples,
                                      std::size_t& count) {
  std::map<std::tuple<long, long, long>, std::size_t> index;
  std::vector<std::size_t> squareOf;
  for (const ReflectionSample& s : samples) {
    const auto key = std::make_tuple(std::lround(std::floor(s.xMeters.y / kSplitCellMeters)),
                                     std::lround(std::floor(s.xMeters.x / kSplitCellMeters)),
                                     std::lround(std::floor(s.xMeters.z / 2.0)));
    squareOf.push_back(index.emplace(key, index.size()).first->second);
  }
  count = index.size();
  return squareOf;
}

// The p95 of the split: each square shaded by the probe that leaves fewer of its samples over
// the tolerance (then the lower sum): a split an artist can draw, not a choice per reflection.
double splitP95(std::span<const std::size_t> squareOf, std::size_t squareCount,
                std::span<const double> first, std::span<const double> other, double toleranceDeg) {
  struct Score {
    std::ptrdiff_t over = 0;
    double sum = 0.0;
    bool operator<(const Score& b) const { return std::tie(over, sum) < std::tie(b.over, b.sum); }
  };
  std::vector<Score> firstScore(squareCount), otherScore(squareCount);
  for (std::size_t i = 0; i < squareOf.size(); ++i) {
    Score& f = firstScore[squareOf[i]];
    Score& o = otherScore[squareOf[i]];
    f.over += first[i] > toleranceDeg, f.sum += first[i];
    o.over += other[i] > toleranceDeg, o.sum += other[i];
  }
  std::vector<double> errors;
  for (std::size_t i = 0; i < squareOf.size(); ++i) {
    const bool toOther = otherScore[squareOf[i]] < firstScore[squareOf[i]];
    errors.push_back(toOther ? other[i] : first[i]);
  }
  if (errors.empty()) return std::numeric_limits<double>::quiet_NaN();
  return summarizeErrors(std::move(errors), 0).p95Deg;
}

}  // namespace

void checkSplitProbe(const LevelRayCaster& level, const Probe& probe, const ProxyShape& own,
                     double ownP95Deg, std::span<const ReflectionSample> samples,
                     const std::vector<FloorCell>& floor, const ValidateOptions& options,
                     std::vector<ValidationFinding>& out) {
  const std::vector<glm::dvec3> captures = capturesToTry(level, probe, floor);
  ProxyBuildOptions coarse = LayoutOptions::coarseCandidateProxyOptions();
  coarse.toleranceDeg = options.toleranceDeg;
  // What does not depend on the second probe, once: each sample's square and its error with
  // the probe's own proxy. A sample a capture point cannot see is a miss for that probe (its
  // cubemap shows something else there).
  std::size_t squareCount = 0;
  const std::vector<std::size_t> squareOf = splitSquares(samples, squareCount);
  const auto errorOf = [](double e) { return std::isnan(e) ? kMissErrorDeg : e; };
  std::vector<double> ownErrors;
  for (const ReflectionSample& s : samples)
    ownErrors.push_back(s.occluded ? kMissErrorDeg
                                   : errorOf(angularErrorDeg(own, probe.captureMeters, s)));
  std::vector<double> p95(captures.size(), std::numeric_limits<double>::quiet_NaN());
  // The second probe's proxy is fitted to a room, a few rooms, or all it sees (layout's fit
  // regions, candidate_service.h), from one depth cube and hull; the one that splits best
  // counts.
  tbb::parallel_for(std::size_t{0}, captures.size(), [&](std::size_t i) {
    const glm::dvec3 second = captures[i];
    std::vector<char> hidden;
    for (const ReflectionSample& s : samples) hidden.push_back(trueHitHiddenFrom(level, second, s));
    const ProbeView view = seeLevel(level, second, coarse.depthFaceSize);
    const ViewHull hull = fitViewHull(view);
    for (const double fit : {kRoomFitMeters, kRoomsFitMeters, kAllItSeesFitMeters}) {
      const ProbeProxyBuild build =
          buildProbeProxy(level, candidateFitProbe(second, fit), view, hull, std::nullopt, coarse);
      const ProxyShape& proxy = build.candidates[build.kept].shape;
      std::vector<double> otherErrors;
      for (std::size_t k = 0; k < samples.size(); ++k)
        otherErrors.push_back(hidden[k] ? kMissErrorDeg
                                        : errorOf(angularErrorDeg(proxy, second, samples[k])));
      const double split =
          splitP95(squareOf, squareCount, ownErrors, otherErrors, options.toleranceDeg);
      if (!std::isnan(split) && !(split >= p95[i])) p95[i] = split;
    }
  });
  std::size_t best = captures.size();  // the lowest p95, the first of equals
  for (std::size_t i = 0; i < captures.size(); ++i)
    if (!std::isnan(p95[i]) && (best == captures.size() || p95[i] < p95[best])) best = i;
  if (best == captures.size() || p95[best] > options.toleranceDeg) return;

  const glm::dvec3 at = captures[best];
  char text[256];
  std::snprintf(text, sizeof text,
                "': a second probe at %s would bring its floor's mirror_floor p95 from %.2f to "
                "%.2f deg (each square metre of floor shaded by the better of the two)",
                formatPoint(at).c_str(), ownP95Deg, p95[best]);
  out.push_back({probe.name, "split_probe", "info", p95[best], options.toleranceDeg,
                 "probe '" + probe.name + text,
                 "add a probe at " + formatPoint(at) + " and split '" + probe.name +
                     "''s influence volume between the two (`probeproxy layout --keep-authored` "
                     "places probes and volumes where the scene fails)"});
}

}  // namespace probeproxy
