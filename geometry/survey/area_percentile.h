#pragma once
// Area-weighted percentiles: each value stands for a piece of floor. Nearest rank on the
// cumulative area, so a percentile is always one of the values (as core/measures/
// error_figures.h's are by sample count).

#include <span>
#include <utility>
#include <vector>

namespace probeproxy {

struct AreaValue {
  double value = 0.0;
  double areaSquareMeters = 0.0;  // > 0
};

// The smallest value v such that the values <= v hold at least `fraction` (0..1) of the total
// area. NaN when there is no value. Reorders `values`.
double areaPercentile(std::vector<AreaValue>& values, double fraction);

}  // namespace probeproxy
