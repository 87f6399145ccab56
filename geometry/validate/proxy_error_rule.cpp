// proxy_error_over_tolerance: the authored proxy against the real level, on the floor the probe
// serves in the blend, with the proxy probeproxy would generate beside it, so the artist sees
// whether a better one exists.
//
// Each mirror_floor sample of the probe's outer range counts by the probe's blend weight there
// (Lagarde's, over every volume of the scene): floor a neighbour carries counts for little or
// nothing. Counted whole instead, a probe was judged on band floor its neighbour serves, and
// every layout probe failed (97-132 warnings on a corpus layout) with the hint to use the
// generated proxy, the one the layout had chosen. The value is the weighted p95, a miss at 180
// degrees as the survey counts it. A proxy is worse than the generated one when the generated
// leaves less of that weighted floor over the tolerance (a miss counts as over): the layout's
// own rule, by at least kClearlyLessFloor, as the build fits on samples of its own. Where none
// is clearly better, the finding is information: what the floor gets, and that a second probe
// (split_probe) or accepting it is what is left.

#include "core/blend/blend_weights.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/survey/area_percentile.h"
#include "geometry/survey/blended_error.h"
#include "geometry/validate/validation_rules.h"

#include <cmath>
#include <cstdio>

namespace probeproxy {

namespace {

constexpr double kClearlyLessFloor = 0.02;  // share of the served floor's weight

struct ServedError {
  double p95Deg = 0.0;     // weighted, a miss at 180 degrees; NaN: no weighted visible sample
  double overShare = 0.0;  // weighted share over the tolerance, misses included
};

ServedError servedError(const ProxyShape& shape, glm::dvec3 capture,
                        const std::vector<ReflectionSample>& samples,
                        const std::vector<double>& weights, double toleranceDeg) {
  std::vector<AreaValue> weighted;
  double total = 0.0, over = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].occluded || weights[i] <= 0.0) continue;
    const double e = angularErrorDeg(shape, capture, samples[i]);
    const double cost = std::isnan(e) ? kMissErrorDeg : e;
    weighted.push_back({cost, weights[i]});
    total += weights[i];
    if (!(e <= toleranceDeg)) over += weights[i];
  }
  return {areaPercentile(weighted, 0.95), total > 0.0 ? over / total : 0.0};
}

}  // namespace

void checkProxyError(const LevelRayCaster& level, const Probe& probe,
                     std::span<const InfluenceVolume> volumes, int probeIndex,
                     const ProxyShape& authored, const std::vector<FloorCell>& floor,
                     const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (std::holds_alternative<InfiniteShape>(authored)) return;  // chose no correction
  const std::vector<ReflectionSample> samples =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor, options.samples);
  std::vector<double> weights(samples.size(), 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i)
    for (const ProbeWeight& w : blendWeights(volumes, samples[i].xMeters))
      if (w.probe == probeIndex) weights[i] = w.weight;
  const double tolerance = options.toleranceDeg;
  const ServedError error = servedError(authored, probe.captureMeters, samples, weights, tolerance);
  // No weighted visible sample: nothing to measure (the floor is hidden, or another's).
  if (!(error.p95Deg > tolerance)) return;

  ProxyBuildOptions build;
  build.toleranceDeg = tolerance;
  build.regenerate = true;
  build.samples = options.samples;
  const ProbeProxyBuild generated = buildProbeProxy(level, probe, authored, build);
  const ProxyCandidate& kept = generated.candidates[generated.kept];
  const ServedError generatedError =
      servedError(kept.shape, probe.captureMeters, samples, weights, tolerance);
  const bool generatedBetter = generatedError.overShare + kClearlyLessFloor < error.overShare;

  char text[320];
  std::snprintf(text, sizeof text,
                "' proxy on the floor it serves (weighted by its blend weight): mirror_floor p95 "
                "angular error %.2f deg, %.1f%% over the %.2f deg tolerance; the generated proxy "
                "(%s, %d planes): p95 %.2f deg, %.1f%% over",
                error.p95Deg, 100.0 * error.overShare, tolerance, candidateName(kept).c_str(),
                planeCount(kept.shape), generatedError.p95Deg, 100.0 * generatedError.overShare);
  std::string message = "probe '" + probe.name;
  message += text;
  if (options.measures("proxy_error_over_tolerance")) {
    if (generatedBetter) {
      out.push_back({probe.name, "proxy_error_over_tolerance", "warning", error.p95Deg, tolerance,
                     std::move(message),
                     "use the generated proxy (`\"proxy\": \"auto\"`, or `probeproxy build "
                     "--regenerate` to see it), or move the proxy's faces onto the walls the "
                     "reflections land on"});
    } else {
      out.push_back({probe.name, "proxy_error_over_tolerance", "info", error.p95Deg, tolerance,
                     std::move(message),
                     "no generated proxy serves this floor clearly better: a second probe "
                     "(`probeproxy layout --keep-authored` adds one where it helps) or accepting "
                     "the error is what is left"});
    }
  }
  // Where no proxy of its own serves the floor, a second probe may take the part the probe's
  // own proxy fails (a room box fails the other arm of an L, and a second probe in that arm
  // serves it exactly, where a proxy fitted to both arms serves neither).
  if (generatedError.p95Deg > tolerance && options.measures("split_probe"))
    checkSplitProbe(level, probe, authored, error.p95Deg, samples, floor, options, out);
}

}  // namespace probeproxy
