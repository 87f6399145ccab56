// The timing of a build without Google Benchmark (PROBEPROXY_BUILD_BENCHMARKS=OFF and the
// library not installed): nothing is timed, so every ns figure is reported as null, never as a
// number measured some other, incomparable way. Error figures and instruction counts stand.

#include "plugin/jobs/bench/lookup_timing.h"

namespace probeproxy::jobs {

void keepResult(const void*) {}

Timings timeBenchmarks(const std::vector<TimingJob>& jobs, const std::vector<CallJob>& callJobs,
                       const TimingOptions&, const std::function<void(std::size_t, std::size_t)>&) {
  Timings timings;
  timings.lookups.resize(jobs.size());
  timings.nsPerItem.resize(callJobs.size());
  return timings;
}

}  // namespace probeproxy::jobs
