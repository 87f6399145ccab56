#include "geometry/tune/one_dimensional_fits.h"

#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/tune/sample_cost.h"

#include <cmath>
#include <functional>

namespace probeproxy {

namespace {

double meanCost(const ProxyShape& shape, glm::dvec3 capture,
                std::span<const ReflectionSample> samples) {
  const std::vector<double> errors = angularErrorsDeg(shape, capture, samples);
  double sum = 0.0;
  for (double e : errors) sum += sampleCostDeg(e);
  return errors.empty() ? 0.0 : sum / static_cast<double>(errors.size());
}

// Golden-section search on [lo, hi] after a coarse scan, because the cost is not unimodal
// everywhere (misses switch on and off as the radius crosses sample points).
double minimize(const std::function<double(double)>& cost, double lo, double hi) {
  constexpr int kScan = 24;
  double best = lo, bestCost = cost(lo);
  for (int i = 1; i <= kScan; ++i) {
    const double v = lo + (hi - lo) * i / kScan;
    const double c = cost(v);
    if (c < bestCost) best = v, bestCost = c;
  }
  const double step = (hi - lo) / kScan;
  double a = std::max(lo, best - step), b = std::min(hi, best + step);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double c1 = b - g * (b - a), c2 = a + g * (b - a);
  double f1 = cost(c1), f2 = cost(c2);
  for (int i = 0; i < 30; ++i) {
    if (f1 < f2) {
      b = c2, c2 = c1, f2 = f1, c1 = b - g * (b - a), f1 = cost(c1);
    } else {
      a = c1, c1 = c2, f1 = f2, c2 = a + g * (b - a), f2 = cost(c2);
    }
  }
  const double inner = f1 < f2 ? c1 : c2;
  return std::min(f1, f2) < bestCost ? inner : best;
}

}  // namespace

CheapKShape fitCheapK(glm::dvec3 capture, std::span<const ReflectionSample> samples,
                      double typicalDistanceMeters) {
  const double hi = 4.0 / std::max(typicalDistanceMeters, 1e-3);
  const double k =
      minimize([&](double kPerMeter) { return meanCost(CheapKShape{kPerMeter}, capture, samples); },
               0.0, hi);
  return CheapKShape{k};
}

SphereShape fitCaptureSphere(glm::dvec3 capture, std::span<const ReflectionSample> samples,
                             double nearestMeters, double farthestMeters) {
  const auto sphere = [&](double radius) {
    return SphereShape{capture, glm::dvec3(radius), glm::dquat(1, 0, 0, 0)};
  };
  const double radius =
      minimize([&](double r) { return meanCost(sphere(r), capture, samples); },
               std::max(nearestMeters, 1e-3), std::max(farthestMeters, nearestMeters + 1e-3));
  return sphere(radius);
}

}  // namespace probeproxy
