#include "geometry/tune/greedy_plane_removal.h"

#include "core/parallax/reference_lookup.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/tune/sample_cost.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace probeproxy {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Per-sample, per-plane numbers computed once, so that trying the removal of a plane only
// touches the samples whose exit plane (or only violated plane) it is.
class RemovalState {
 public:
  RemovalState(const std::vector<ProxyPlane>& planes, glm::dvec3 capture,
               std::span<const ReflectionSample> allSamples)
      : planeCount_(planes.size()), active_(planes.size(), true) {
    for (const ReflectionSample& s : allSamples) {
      if (s.occluded) continue;
      Sample sample;
      sample.origin = s.xMeters;
      sample.direction = s.reflected;
      sample.ideal = s.hitsSky ? s.reflected : s.trueHitMeters - capture;
      samples_.push_back(sample);
    }
    capture_ = capture;
    exitT_.resize(samples_.size() * planeCount_);
    outside_.resize(samples_.size() * planeCount_);
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      for (std::size_t j = 0; j < planeCount_; ++j) {
        const ProxyPlane& p = planes[j];
        const double beyond = glm::dot(p.normal, samples_[i].origin) - p.offsetMeters;
        const double towards = glm::dot(p.normal, samples_[i].direction);
        outside_[i * planeCount_ + j] = beyond > kInsideToleranceMeters;
        exitT_[i * planeCount_ + j] = towards > 0 ? std::max(0.0, -beyond) / towards : kInfinity;
      }
      refresh(i);
    }
  }

  double totalCost() const {
    double sum = 0.0;
    for (const Sample& s : samples_) sum += s.cost;
    return sum;
  }
  std::size_t sampleCount() const { return samples_.size(); }

  // The change in total cost if plane j went, for every plane at once: a sample's cost depends
  // on one plane only (the one it exits through, or the only one it lies outside of), so one
  // pass over the samples finds them all. Each plane's sum runs in sample order, as it would
  // plane by plane: the same bits.
  std::vector<double> costsOfRemoving() const {
    std::vector<double> delta(planeCount_, 0.0);
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      if (s.violations == 1) {
        delta[s.violator] += costAt(i, exitWithout(i, s.violator)) - s.cost;
      } else if (s.violations == 0 && s.exitPlane < planeCount_) {
        delta[s.exitPlane] += costAt(i, s.secondT) - s.cost;
      }
    }
    return delta;
  }

  void remove(std::size_t j) {
    active_[j] = false;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      if (s.exitPlane == j || s.secondPlane == j || outside_[i * planeCount_ + j]) refresh(i);
    }
  }

  bool isActive(std::size_t j) const { return active_[j]; }

 private:
  struct Sample {
    glm::dvec3 origin, direction, ideal;
    std::size_t violations = 0, violator = 0;  // active planes x is outside of
    std::size_t exitPlane = 0, secondPlane = 0;
    double exitT = kInfinity, secondT = kInfinity;
    double cost = 0.0;
  };

  double costAt(std::size_t i, double t) const {
    if (!std::isfinite(t)) return kMissCostDeg;
    const Sample& s = samples_[i];
    const glm::dvec3 d = s.origin + t * s.direction - capture_;
    if (d == glm::dvec3(0.0)) return kMissCostDeg;
    return angleBetweenDeg(d, s.ideal);
  }

  double exitWithout(std::size_t i, std::size_t skip) const {
    double t = kInfinity;
    for (std::size_t j = 0; j < planeCount_; ++j) {
      if (active_[j] && j != skip) t = std::min(t, exitT_[i * planeCount_ + j]);
    }
    return t;
  }

  void refresh(std::size_t i) {
    Sample& s = samples_[i];
    s.violations = 0;
    s.exitT = s.secondT = kInfinity;
    s.exitPlane = s.secondPlane = planeCount_;
    for (std::size_t j = 0; j < planeCount_; ++j) {
      if (!active_[j]) continue;
      if (outside_[i * planeCount_ + j]) ++s.violations, s.violator = j;
      const double t = exitT_[i * planeCount_ + j];
      if (t < s.exitT) {
        s.secondT = s.exitT, s.secondPlane = s.exitPlane;
        s.exitT = t, s.exitPlane = j;
      } else if (t < s.secondT) {
        s.secondT = t, s.secondPlane = j;
      }
    }
    s.cost = s.violations > 0 ? kMissCostDeg : costAt(i, s.exitT);
  }

  std::size_t planeCount_;
  std::vector<bool> active_;
  std::vector<Sample> samples_;
  glm::dvec3 capture_{0.0};
  std::vector<double> exitT_;  // [sample][plane]: where the ray crosses the plane; inf if never
  std::vector<char> outside_;  // [sample][plane]: x beyond the plane
};

// The planes still active, less `skip` (pass planes.size() to skip none).
std::vector<ProxyPlane> activePlanes(const std::vector<ProxyPlane>& planes,
                                     const RemovalState& state, std::size_t skip) {
  std::vector<ProxyPlane> kept;
  for (std::size_t j = 0; j < planes.size(); ++j) {
    if (state.isActive(j) && j != skip) kept.push_back(planes[j]);
  }
  return kept;
}

}  // namespace

std::vector<PlaneRemovalStep> greedyPlaneRemoval(const std::vector<ProxyPlane>& planes,
                                                 glm::dvec3 capture,
                                                 std::span<const ReflectionSample> samples,
                                                 int minPlanes, const PlaneRemovalRule& rule) {
  RemovalState state(planes, capture, samples);
  const double perSample = 1.0 / std::max<std::size_t>(1, state.sampleCount());
  std::vector<PlaneRemovalStep> steps = {{planes, state.totalCost() * perSample}};

  for (std::size_t count = planes.size(); count > static_cast<std::size_t>(std::max(minPlanes, 4));
       --count) {
    // Cheapest removal first; the acceptability test (an exact boundedness test, and the
    // caller's own) runs only until one passes.
    std::vector<std::pair<double, std::size_t>> order;
    const std::vector<double> costs = state.costsOfRemoving();
    for (std::size_t j = 0; j < planes.size(); ++j) {
      if (state.isActive(j)) order.emplace_back(costs[j], j);
    }
    std::sort(order.begin(), order.end());  // ties go to the lower index: the same every run
    std::size_t best = planes.size();
    for (const auto& [delta, j] : order) {
      if (rule.accepts(activePlanes(planes, state, j), j)) {
        best = j;
        break;
      }
    }
    if (best == planes.size()) break;  // every remaining plane is needed
    state.remove(best);
    if (rule.removed) rule.removed(best);
    steps.push_back({activePlanes(planes, state, planes.size()), state.totalCost() * perSample});
  }
  return steps;
}

}  // namespace probeproxy
