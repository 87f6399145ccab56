#include "geometry/probe_proxies/probe_samples.h"

namespace probeproxy {

ProbeSamples drawProbeSamples(const LevelRayCaster& level, const Probe& probe,
                              const ProxyBuildOptions& o) {
  ProbeSamples s;
  ReflectionSampleOptions fitOptions = o.samples;
  fitOptions.connectedFloorOnly = true;
  ReflectionSampleOptions reportOptions = o.samples;
  reportOptions.seed = o.samples.seed + 1000;
  reportOptions.connectedFloorOnly = false;
  Probe fitProbe = probe;
  if (o.fitInfluence) fitProbe.influence = *o.fitInfluence;
  const std::optional<WalkableFloor> served = servedFloor(level, fitProbe, fitOptions);
  s.fit = buildReflectionSamples(level, fitProbe, SampleSet::MirrorFloor, fitOptions, served);
  for (const ReflectionSample& r :
       buildReflectionSamples(level, fitProbe, SampleSet::AllSurfaces, fitOptions, served))
    s.fit.push_back(r);
  s.floor = buildReflectionSamples(level, probe, SampleSet::MirrorFloor, reportOptions);
  s.all = buildReflectionSamples(level, probe, SampleSet::AllSurfaces, reportOptions);
  return s;
}

}  // namespace probeproxy
