#include "geometry/layout/candidate_service.h"

#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/survey/blended_error.h"

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>

namespace probeproxy {

Probe candidateFitProbe(glm::dvec3 captureMeters, double fitMeters) {
  Probe probe;
  probe.name = "candidate";
  probe.captureMeters = captureMeters;
  probe.influence = SphereInfluence{captureMeters, fitMeters, fitMeters};
  return probe;
}

CandidateService serveFloor(const LevelRayCaster& level, glm::dvec3 captureMeters,
                            double fitMeters, std::span<const FloorSample> samples,
                            const LayoutOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  CandidateService s;
  s.captureMeters = captureMeters;
  s.fitMeters = fitMeters;
  const ProbeProxyBuild build = buildProbeProxy(level, candidateFitProbe(captureMeters, fitMeters),
                                                std::nullopt, o.candidateProxy);
  s.proxy = build.candidates[build.kept].shape;

  const double reach2 = o.reachMeters * o.reachMeters;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const ReflectionSample& sample = samples[i].sample;
    const glm::dvec3 d = sample.xMeters - captureMeters;
    if (glm::dot(d, d) > reach2) continue;
    if (trueHitHiddenFrom(level, captureMeters, sample)) continue;
    const double error = angularErrorDeg(s.proxy, captureMeters, sample);
    s.samples.push_back(static_cast<std::uint32_t>(i));
    s.errorDeg.push_back(static_cast<float>(std::isnan(error) ? kMissErrorDeg : error));
  }
  s.buildMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace probeproxy
