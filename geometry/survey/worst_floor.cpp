#include "geometry/survey/worst_floor.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace probeproxy {

namespace {

// A hit is inside the proxy when the ray, this far on past the level surface, still is: a
// surface on a proxy face (the wall the proxy was fitted to) has the ray leave the proxy there.
constexpr double kInsideMarginMeters = 0.1;

}  // namespace

WorstFloor worstFloor(std::span<const SurveySampleError> errors,
                      std::span<const FloorSample> samples, double thresholdDeg,
                      const std::function<SurveyProbeRef(int)>& probeOf) {
  WorstFloor w;
  w.thresholdDeg = thresholdDeg;
  if (!std::isfinite(thresholdDeg)) return w;
  double sky = 0.0, near = 0.0, inside = 0.0;
  std::map<int, double> byProbe;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    const SurveySampleError& e = errors[i];
    if (std::isnan(e.errorDeg) || e.errorDeg < thresholdDeg) continue;
    const double area = shadedArea(e);
    const ReflectionSample& s = samples[i].sample;
    w.squareMeters += area;
    const SurveyProbeRef probe = probeOf(e.heaviestProbe);
    byProbe[probe.sceneProbe] += area;
    if (s.hitsSky) {
      sky += area;
      continue;
    }
    if (glm::length(s.trueHitMeters - s.xMeters) < kNearHitMeters) near += area;
    if (strictlyContains(*probe.proxy, s.trueHitMeters + kInsideMarginMeters * s.reflected))
      inside += area;
  }
  if (w.squareMeters <= 0.0) return w;
  w.skyShare = sky / w.squareMeters;
  w.nearHitShare = near / w.squareMeters;
  w.hitInsideProxyShare = inside / w.squareMeters;
  for (const auto& [probe, area] : byProbe) w.probes.push_back({probe, area / w.squareMeters});
  std::stable_sort(w.probes.begin(), w.probes.end(),
                   [](const auto& a, const auto& b) { return a.share > b.share; });
  return w;
}

}  // namespace probeproxy
