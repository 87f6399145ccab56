// proxy_error_over_tolerance: the authored proxy against the real level, on the floor the probe
// serves in the blend, with the proxy probeproxy would generate for that floor beside it, so
// the artist sees whether a better one exists.
//
// The floor a probe serves is its majority range (geometry/layout/layout_proxy.h): where its
// weight is at least a neighbour's. Measured over the whole outer range instead, a probe is
// judged on band floor its neighbour carries, and every layout probe failed (97-132 warnings
// on a corpus layout) with the hint to use the generated proxy, the one the layout had chosen.
// A proxy is worse than the generated one when the generated leaves less of that floor over
// the tolerance (a miss counts as over), the layout's own rule; by at least kClearlyLessFloor,
// as the two sample sets differ. Where none is clearly better, the finding is information:
// what the floor gets, and that a second probe (split_probe) or accepting it is what is left.

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/layout/layout_proxy.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/validate/validation_rules.h"

#include <algorithm>
#include <cstdio>

namespace probeproxy {

namespace {

constexpr double kClearlyLessFloor = 0.02;  // share of the served floor's samples

double shareOver(const ProxyShape& shape, glm::dvec3 capture,
                 const std::vector<ReflectionSample>& samples, double toleranceDeg) {
  const std::vector<double> errors = angularErrorsDeg(shape, capture, samples);
  if (errors.empty()) return 0.0;
  const auto over = std::count_if(errors.begin(), errors.end(),
                                  [&](double e) { return !(e <= toleranceDeg); });  // NaN: miss
  return static_cast<double>(over) / static_cast<double>(errors.size());
}

}  // namespace

void checkProxyError(const LevelRayCaster& level, const Probe& probe, const ProxyShape& authored,
                     const std::vector<FloorCell>& floor, const ValidateOptions& options,
                     std::vector<ValidationFinding>& out) {
  if (std::holds_alternative<InfiniteShape>(authored)) return;  // chose no correction
  Probe served = probe;
  served.influence = majorityRange(probe.influence);
  const std::vector<ReflectionSample> samples =
      buildReflectionSamples(level, served, SampleSet::MirrorFloor, options.samples);
  const ErrorFigures error = evaluateShape(authored, probe.captureMeters, samples);
  // No visible sample: nothing to measure (the floor is hidden from the capture point).
  if (!(error.p95Deg > options.toleranceDeg)) return;

  ProxyBuildOptions build;
  build.toleranceDeg = options.toleranceDeg;
  build.regenerate = true;
  build.samples = options.samples;
  const ProbeProxyBuild generated = buildProbeProxy(level, served, authored, build);
  const ProxyCandidate& kept = generated.candidates[generated.kept];
  const double authoredOver =
      shareOver(authored, probe.captureMeters, samples, options.toleranceDeg);
  const double generatedOver =
      shareOver(kept.shape, probe.captureMeters, samples, options.toleranceDeg);
  const bool generatedBetter = generatedOver + kClearlyLessFloor < authoredOver;

  char text[320];
  std::snprintf(text, sizeof text,
                "' proxy on the floor it serves: mirror_floor p95 angular error %.2f deg (median "
                "%.3f, %.1f%% misses, %.1f%% over the %.2f deg tolerance); the generated proxy "
                "(%s, %d planes): p95 %.2f deg, %.1f%% over",
                error.p95Deg, error.medianDeg, 100.0 * error.missRate, 100.0 * authoredOver,
                options.toleranceDeg, candidateName(kept).c_str(), planeCount(kept.shape),
                kept.error.p95Deg, 100.0 * generatedOver);
  std::string message = "probe '" + probe.name;
  message += text;
  if (options.measures("proxy_error_over_tolerance")) {
    if (generatedBetter) {
      out.push_back({probe.name, "proxy_error_over_tolerance", "warning", error.p95Deg,
                     options.toleranceDeg, std::move(message),
                     "use the generated proxy (`\"proxy\": \"auto\"`, or `probeproxy build "
                     "--regenerate` to see it), or move the proxy's faces onto the walls the "
                     "reflections land on"});
    } else {
      out.push_back({probe.name, "proxy_error_over_tolerance", "info", error.p95Deg,
                     options.toleranceDeg, std::move(message),
                     "no generated proxy serves this floor clearly better: a second probe "
                     "(`probeproxy layout --keep-authored` adds one where it helps) or accepting "
                     "the error is what is left"});
    }
  }
  // Where no proxy of its own will do, a second probe may.
  const ProxyShape& best = generatedBetter ? kept.shape : authored;
  const double bestP95 = generatedBetter ? kept.error.p95Deg : error.p95Deg;
  if (bestP95 > options.toleranceDeg && options.measures("split_probe"))
    checkSplitProbe(level, probe, best, bestP95, samples, floor, options, out);
}

}  // namespace probeproxy
