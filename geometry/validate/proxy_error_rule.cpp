// proxy_error_over_tolerance: the authored proxy against the real level, on the floor the probe
// serves in the blend, with the proxy probeproxy would generate beside it, so the artist sees
// whether a better one exists.
//
// The proxy is judged on the floor it serves in the blend (geometry/survey/served_error.h).
// Counted whole instead, a probe was judged on band floor its neighbour serves, and every
// layout probe failed (97-132 warnings on a corpus layout) with the hint to use the generated
// proxy, the one the layout had chosen. The value is the weighted p95, a miss at 180 degrees as
// the survey counts it. A proxy is worse than the generated one when the generated serves that
// floor clearly better (servesClearlyBetter: less of it over the tolerance, the tail no worse
// unless gross already), the rule the layout keeps its own proxy by. Where none is clearly
// better, the finding is information: what the floor gets, and that a second probe
// (split_probe) or accepting it is what is left.

#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/survey/served_error.h"
#include "geometry/validate/validation_rules.h"

#include <cstdio>

namespace probeproxy {

void checkProxyError(const LevelRayCaster& level, const Probe& probe,
                     std::span<const InfluenceVolume> volumes, int probeIndex,
                     const ProxyShape& authored, const std::vector<FloorCell>& floor,
                     const ValidateOptions& options, std::vector<ValidationFinding>& out) {
  if (std::holds_alternative<InfiniteShape>(authored)) return;  // chose no correction
  const std::vector<ReflectionSample> samples =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor, options.samples);
  const std::vector<double> weights = servedWeights(volumes, probeIndex, samples);
  const double tolerance = options.toleranceDeg;
  const ServedError error = servedError(authored, probe.captureMeters, samples, weights, tolerance);
  // No weighted visible sample: nothing to measure (the floor is hidden, or another's).
  if (!(error.p95Deg > tolerance)) return;

  const ProbeProxyBuild generated =
      buildProbeProxy(level, probe, authored, generatedForComparison(tolerance, options.samples));
  const ProxyCandidate& kept = generated.candidates[generated.kept];
  const ServedError generatedError =
      servedError(kept.shape, probe.captureMeters, samples, weights, tolerance);
  const bool generatedBetter = servesClearlyBetter(generatedError, error);

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
