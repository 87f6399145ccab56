#include "geometry/layout/layout_proxy.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/probe_proxies/ieee_float_mode.h"
#include "geometry/probe_proxies/probe_samples.h"
#include "geometry/probe_proxies/probe_view.h"

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

double meanCostOver(const ProbeProxyBuild& build, glm::dvec3 capture,
                    std::span<const ReflectionSample> floor) {
  return evaluateShape(build.candidates[build.kept].shape, capture, floor).meanCostDeg;
}

}  // namespace

InfluenceVolume majorityRange(const InfluenceVolume& influence) {
  return bandCutTo(influence, kMajorityShareOfBand);
}

ProbeProxyBuild buildLayoutProxy(const LevelRayCaster& level, const Probe& probe,
                                 const ProxyBuildOptions& options, double candidateFitMeters) {
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
  double keptCost = 0.0;
  for (const InfluenceVolume& fit : fits) {
    Probe fitted = inner;
    fitted.influence = fit;
    samples.fit = drawFitSamples(level, fitted, options);
    ProbeProxyBuild build = buildProbeProxy(inner, view, hull, samples, std::nullopt, options);
    const double cost = meanCostOver(build, capture, floor);
    // A NaN cost (no visible sample) compares false: the first fit stays.
    if (kept.candidates.empty() || cost < keptCost) kept = std::move(build), keptCost = cost;
  }
  return kept;
}

}  // namespace probeproxy
