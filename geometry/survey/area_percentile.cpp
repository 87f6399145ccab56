#include "geometry/survey/area_percentile.h"

#include <algorithm>
#include <limits>

namespace probeproxy {

double areaPercentile(std::vector<AreaValue>& values, double fraction) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end(),
            [](const AreaValue& a, const AreaValue& b) { return a.value < b.value; });
  double total = 0.0;
  for (const AreaValue& v : values) total += v.areaSquareMeters;
  // A relative margin, so an exact 50% of equal areas lands on the lower value as it should
  // rather than on rounding.
  const double target = fraction * total * (1.0 - 1e-12);
  double cumulative = 0.0;
  for (const AreaValue& v : values) {
    cumulative += v.areaSquareMeters;
    if (cumulative >= target) return v.value;
  }
  return values.back().value;
}

}  // namespace probeproxy
