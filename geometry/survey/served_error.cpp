#include "geometry/survey/served_error.h"

#include "core/blend/blend_weights.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/survey/area_percentile.h"
#include "geometry/survey/blended_error.h"

#include <cmath>

namespace probeproxy {

std::vector<double> servedWeights(std::span<const InfluenceVolume> volumes, int probeIndex,
                                  std::span<const ReflectionSample> samples) {
  std::vector<double> weights(samples.size(), 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i)
    for (const ProbeWeight& w : blendWeights(volumes, samples[i].xMeters))
      if (w.probe == probeIndex) weights[i] = w.weight;
  return weights;
}

ServedError servedError(const ProxyShape& shape, glm::dvec3 captureMeters,
                        std::span<const ReflectionSample> samples, std::span<const double> weights,
                        double toleranceDeg) {
  std::vector<AreaValue> weighted;
  double total = 0.0, over = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].occluded || weights[i] <= 0.0) continue;
    const double e = angularErrorDeg(shape, captureMeters, samples[i]);
    weighted.push_back({std::isnan(e) ? kMissErrorDeg : e, weights[i]});
    total += weights[i];
    if (!(e <= toleranceDeg)) over += weights[i];
  }
  return {areaPercentile(weighted, 0.95), total > 0.0 ? over / total : 0.0};
}

bool servesClearlyBetter(const ServedError& a, const ServedError& b) {
  const bool lessOver = a.overShare + kClearlyLessServedFloor < b.overShare;
  if (b.p95Deg >= kGrossTailDeg) return lessOver;
  return lessOver && a.p95Deg <= 1.02 * b.p95Deg + 0.05;
}

}  // namespace probeproxy
