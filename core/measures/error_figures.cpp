#include "core/measures/error_figures.h"

#include <algorithm>
#include <cmath>

namespace probeproxy {

ErrorFigures summarizeErrors(std::vector<double> errorsDeg, std::size_t occluded) {
  ErrorFigures figures;
  figures.samples = errorsDeg.size() + occluded;
  if (figures.samples == 0) return figures;
  figures.occludedRate = static_cast<double>(occluded) / static_cast<double>(figures.samples);

  const auto missed =
      std::partition(errorsDeg.begin(), errorsDeg.end(), [](double e) { return !std::isnan(e); });
  const std::size_t hits = static_cast<std::size_t>(missed - errorsDeg.begin());
  const std::size_t visible = errorsDeg.size();
  if (visible > 0) {
    figures.missRate = static_cast<double>(visible - hits) / static_cast<double>(visible);
    double sum = 180.0 * static_cast<double>(visible - hits);
    for (std::size_t i = 0; i < hits; ++i) sum += errorsDeg[i];
    figures.meanCostDeg = sum / static_cast<double>(visible);
    // Misses sort last (180 degrees is as wrong as a lookup gets): the p95 rank lands on one
    // once they are more than 5% of the visible samples.
    const auto k = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(visible)));
    const std::size_t rank = std::clamp<std::size_t>(k, 1, visible);
    if (rank > hits) {
      figures.p95WithMissesDeg = 180.0;
    } else {
      std::vector<double> sorted(errorsDeg.begin(), missed);
      std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(rank - 1),
                       sorted.end());
      figures.p95WithMissesDeg = sorted[rank - 1];
    }
  }
  if (hits == 0) return figures;

  errorsDeg.resize(hits);
  std::sort(errorsDeg.begin(), errorsDeg.end());
  const auto rank = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(hits)));
    return errorsDeg[std::clamp<std::size_t>(k, 1, hits) - 1];
  };
  figures.medianDeg = rank(0.5);
  figures.p95Deg = rank(0.95);
  figures.maxDeg = errorsDeg.back();
  return figures;
}

}  // namespace probeproxy
