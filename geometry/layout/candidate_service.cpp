#include "geometry/layout/candidate_service.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/survey/blended_error.h"

#include <chrono>
#include <cmath>

namespace probeproxy {

std::vector<double> fitRadiiFor(double farthestSeenMeters, double reachMeters) {
  const double widest =
      reachMeters > 0.0 ? std::min(farthestSeenMeters, reachMeters) : farthestSeenMeters;
  std::vector<double> radii;
  for (double r : {kRoomFitMeters, kRoomsFitMeters})
    if (r < widest) radii.push_back(r);
  radii.push_back(std::max(widest, 0.5));
  return radii;
}

Probe candidateFitProbe(glm::dvec3 captureMeters, double fitMeters) {
  Probe probe;
  probe.name = "candidate";
  probe.captureMeters = captureMeters;
  probe.influence = SphereInfluence{captureMeters, fitMeters, fitMeters};
  return probe;
}

std::vector<float> errorsOnSeen(const ProxyShape& proxy, glm::dvec3 captureMeters,
                                std::span<const FloorSample> samples, const IndexSet& seen) {
  std::vector<float> errors;
  errors.reserve(countOf(seen));
  forEachIndex(seen, [&](std::uint32_t i) {
    const double error = angularErrorDeg(proxy, captureMeters, samples[i].sample);
    errors.push_back(static_cast<float>(std::isnan(error) ? kMissErrorDeg : error));
  });
  return errors;
}

CaptureView seeFromCapture(const LevelRayCaster& level, glm::dvec3 captureMeters,
                           const LayoutOptions& o) {
  CaptureView v;
  v.view = seeLevel(level, captureMeters, o.candidateProxy.depthFaceSize);
  v.hull = fitViewHull(v.view);
  return v;
}

CandidateService serveFloor(const LevelRayCaster& level, const CaptureView& v, double fitMeters,
                            std::span<const FloorSample> samples, const IndexSet& seen,
                            const LayoutOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const glm::dvec3 captureMeters = v.view.captureMeters;
  CandidateService s;
  s.captureMeters = captureMeters;
  s.fitMeters = fitMeters;
  const ProbeProxyBuild build = buildProbeProxy(level, candidateFitProbe(captureMeters, fitMeters),
                                                v.view, v.hull, std::nullopt, o.candidateProxy);
  s.proxy = build.candidates[build.kept].shape;
  const std::vector<float> errors = errorsOnSeen(s.proxy, captureMeters, samples, seen);
  std::size_t k = 0;
  forEachIndex(seen, [&](std::uint32_t i) {
    if (errors[k++] <= o.toleranceDeg) s.served.add(i);
  });
  compact(s.served);
  s.buildMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace probeproxy
