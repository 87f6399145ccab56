#include "geometry/probe_proxies/probe_samples.h"

namespace probeproxy {

std::vector<ReflectionSample> drawFitSamples(const LevelRayCaster& level, const Probe& probe,
                                             const ProxyBuildOptions& o) {
  ReflectionSampleOptions fitOptions = o.samples;
  fitOptions.connectedFloorOnly = true;
  const std::optional<WalkableFloor> served = servedFloor(level, probe, fitOptions);
  std::vector<ReflectionSample> fit =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor, fitOptions, served);
  for (const ReflectionSample& r :
       buildReflectionSamples(level, probe, SampleSet::AllSurfaces, fitOptions, served))
    fit.push_back(r);
  return fit;
}

std::vector<ReflectionSample> drawReportSamples(const LevelRayCaster& level, const Probe& probe,
                                                const ProxyBuildOptions& o, SampleSet set) {
  ReflectionSampleOptions reportOptions = o.samples;
  reportOptions.seed = o.samples.seed + 1000;
  reportOptions.connectedFloorOnly = false;
  return buildReflectionSamples(level, probe, set, reportOptions);
}

ProbeSamples drawProbeSamples(const LevelRayCaster& level, const Probe& probe,
                              const ProxyBuildOptions& o) {
  ProbeSamples s;
  s.fit = drawFitSamples(level, probe, o);
  s.floor = drawReportSamples(level, probe, o, SampleSet::MirrorFloor);
  s.all = drawReportSamples(level, probe, o, SampleSet::AllSurfaces);
  return s;
}

}  // namespace probeproxy
