// proxy_error_over_tolerance: the authored proxy against the real level, with the proxy
// probeproxy would generate beside it, so the artist sees whether a better one exists.

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/validate/validation_rules.h"

#include <cstdio>

namespace probeproxy {

void checkProxyError(const LevelRayCaster& level, const Probe& probe, const ProxyShape& authored,
                     const std::vector<FloorCell>& floor, const ValidateOptions& options,
                     std::vector<ValidationFinding>& out) {
  if (std::holds_alternative<InfiniteShape>(authored)) return;  // chose no correction
  const std::vector<ReflectionSample> samples =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor, options.samples);
  const ErrorFigures error = evaluateShape(authored, probe.captureMeters, samples);
  // No visible sample: nothing to measure (the floor is hidden from the capture point).
  if (!(error.p95Deg > options.toleranceDeg)) return;

  ProxyBuildOptions build;
  build.toleranceDeg = options.toleranceDeg;
  build.regenerate = true;
  build.samples = options.samples;
  const ProbeProxyBuild generated = buildProbeProxy(level, probe, authored, build);
  const ProxyCandidate& kept = generated.candidates[generated.kept];

  char text[256];
  std::snprintf(text, sizeof text,
                "' authored proxy: mirror_floor p95 angular error %.2f deg (median %.3f, %.1f%% "
                "misses), over the %.2f deg tolerance; the generated proxy (%s, %d planes): p95 "
                "%.2f deg",
                error.p95Deg, error.medianDeg, 100.0 * error.missRate, options.toleranceDeg,
                candidateName(kept).c_str(), planeCount(kept.shape), kept.error.p95Deg);
  std::string message = "probe '" + probe.name;
  message += text;
  if (options.measures("proxy_error_over_tolerance"))
    out.push_back({probe.name, "proxy_error_over_tolerance", "warning", error.p95Deg,
                   options.toleranceDeg, std::move(message),
                   kept.error.p95Deg < error.p95Deg
                       ? "use the generated proxy (`\"proxy\": \"auto\"`, or `probeproxy build "
                         "--regenerate` to see it), or move the proxy's faces onto the walls "
                         "the reflections land on"
                       : "no convex proxy does better here: split the probe's area between more "
                         "probes, or accept the error"});
  // Where no proxy of its own will do, a second probe may.
  const bool generatedBetter = kept.error.p95Deg < error.p95Deg;
  const double best = generatedBetter ? kept.error.p95Deg : error.p95Deg;
  if (best > options.toleranceDeg && options.measures("split_probe"))
    checkSplitProbe(level, probe, generatedBetter ? kept.shape : authored, best, samples, floor,
                    options, out);
}

}  // namespace probeproxy
