#pragma once
// The error of one correction method with one proxy over one sample set
// (docs/methods_and_measures.md, "Measures"). Angular error = angle(P - C, H - C) in degrees, over
// the samples that are neither occluded nor missed.

#include <cstddef>
#include <limits>
#include <vector>

namespace probeproxy {

struct ErrorFigures {
  double medianDeg = std::numeric_limits<double>::quiet_NaN();
  double p95Deg = std::numeric_limits<double>::quiet_NaN();
  double maxDeg = std::numeric_limits<double>::quiet_NaN();
  // Mean over the visible samples with each miss counted as 180 degrees: one number for "how
  // wrong overall", used to rank proxies when none meets the tolerance.
  double meanCostDeg = std::numeric_limits<double>::quiet_NaN();
  // p95 over the visible samples with each miss counted as 180 degrees: what a player sees of
  // a proxy that misses (the seeds' red pixels), the rank used when none meets the tolerance.
  double p95WithMissesDeg = std::numeric_limits<double>::quiet_NaN();
  double missRate = 0.0;      // misses / (samples - occluded): no proxy hit (the seed's red pixel)
  double occludedRate = 0.0;  // occluded / samples: H hidden from C, right for no proxy
  std::size_t samples = 0;    // all samples of the set, occluded and missed included
};

// One angular error per sample; NaN marks a miss, and occluded samples are not passed in.
// Percentiles are nearest-rank on the sorted errors, so figures are exact sample values.
ErrorFigures summarizeErrors(std::vector<double> errorsDeg, std::size_t occluded);

}  // namespace probeproxy
