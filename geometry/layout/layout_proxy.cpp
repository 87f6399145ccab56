#include "geometry/layout/layout_proxy.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/probe_proxies/ieee_float_mode.h"
#include "geometry/probe_proxies/probe_samples.h"
#include "geometry/probe_proxies/probe_view.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <variant>
#include <vector>

namespace probeproxy {

namespace {

constexpr double kMajorityShareOfBand = 0.5 / kOuterBandOverGap;  // half the gap

// The influence with its outer boundary `share` of the way from its inner range to where it was.
InfluenceVolume bandCutTo(InfluenceVolume influence, double share) {
  if (auto* box = std::get_if<BoxInfluence>(&influence))
    box->halfExtentsMeters = box->innerHalfExtentsMeters +
                             share * (box->halfExtentsMeters - box->innerHalfExtentsMeters);
  else if (auto* sphere = std::get_if<SphereInfluence>(&influence))
    sphere->radiusMeters =
        sphere->innerRadiusMeters + share * (sphere->radiusMeters - sphere->innerRadiusMeters);
  return influence;
}

// How a fit's kept proxy serves the floor a player sees it on: the share over the tolerance
// first, as the survey counts it. Chosen by mean cost alone, the fit with the fewest misses won
// where another modelled more of the floor within the tolerance (chosen this way instead:
// toxic's floor over 5 deg 24.7% -> 22.7%, warfare's 26.9% -> 25.3%). To the percent: on the
// 2048 report samples two shares closer than that are sampling noise (a standard error of 0.9
// points at 20%).
struct FitScore {
  double percentOver = 0.0;
  double meanCostDeg = 0.0;
  bool operator<(const FitScore& o) const {
    return percentOver < o.percentOver ||
           (percentOver == o.percentOver && meanCostDeg < o.meanCostDeg);
  }
};

FitScore scoreOn(const ProbeProxyBuild& build, glm::dvec3 capture,
                 std::span<const ReflectionSample> floor, double toleranceDeg) {
  const ProxyShape& shape = build.candidates[build.kept].shape;
  std::vector<double> errors = angularErrorsDeg(shape, capture, floor);
  const auto over = std::count_if(errors.begin(), errors.end(), [&](double e) {
    return !(e <= toleranceDeg);  // a miss (NaN) is over
  });
  FitScore score;
  if (!errors.empty()) score.percentOver = std::round(100.0 * double(over) / double(errors.size()));
  const std::size_t occluded = floor.size() - errors.size();
  score.meanCostDeg = summarizeErrors(std::move(errors), occluded).meanCostDeg;
  return score;
}

}  // namespace

InfluenceVolume majorityRange(const InfluenceVolume& influence) {
  return bandCutTo(influence, kMajorityShareOfBand);
}

ProbeProxyBuild buildLayoutProxy(const LevelRayCaster& level, const Probe& probe,
                                 ProxyBuildOptions options, double candidateFitMeters,
                                 double toleranceDeg) {
  // The kept proxy is written into the layout's scene file: it must be one a scene can hold,
  // or `build` and `survey` on that scene would measure another.
  options.sceneShapesOnly = true;
  // No simplification step misses a lookup from the floor it was fitted to; with the fits
  // chosen by the floor over the tolerance, that took p95 and the floor over 5 deg down
  // together (proxy_build_options.h).
  options.simplifyHoldingFloor = true;
  // Chosen on the floor the probe alone lights: in the band a neighbour carries part of the
  // weight, and counted whole, floor there that the probe's own room does not hold outweighs
  // that room (fitted and chosen on the whole box, warfare's p95 was 36.9 deg against 35.3).
  Probe inner = probe;
  inner.influence = bandCutTo(probe.influence, 0.0);
  Probe majority = probe;
  majority.influence = majorityRange(probe.influence);

  const IeeeFloatMode ieee;  // as the build runs: the figures do not depend on the thread
  const std::vector<ReflectionSample> floor =
      drawReportSamples(level, majority, options, SampleSet::MirrorFloor);

  const glm::dvec3 capture = probe.captureMeters;
  std::vector<InfluenceVolume> fits = {inner.influence, majority.influence};
  if (candidateFitMeters > 0.0)
    fits.push_back(candidateFitProbe(capture, candidateFitMeters).influence);
  // One depth cube, hull and report for the three: the capture point and the inner range are
  // the same; only the reflections fitted to differ.
  const ProbeView view = seeLevel(level, capture, options.depthFaceSize);
  const ViewHull hull = fitViewHull(view);
  // No all_surfaces set: layout reports no figure on it (only `build --json` does).
  ProbeSamples samples;
  samples.floor = drawReportSamples(level, inner, options, SampleSet::MirrorFloor);
  ProbeProxyBuild kept;
  FitScore keptScore;
  for (const InfluenceVolume& fit : fits) {
    Probe fitted = inner;
    fitted.influence = fit;
    samples.fit = drawFitSamples(level, fitted, options);
    ProbeProxyBuild build = buildProbeProxy(inner, view, hull, samples, std::nullopt, options);
    const FitScore score = scoreOn(build, capture, floor, toleranceDeg);
    // A NaN mean (no visible sample) compares false: the first fit stays.
    if (kept.candidates.empty() || score < keptScore) kept = std::move(build), keptScore = score;
  }
  return kept;
}

}  // namespace probeproxy
