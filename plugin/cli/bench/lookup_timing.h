#pragma once
// ns per lookup of prepared proxies, measured with Google Benchmark inside the CLI: each
// proxy is timed on the same rays through the scalar seed-code port (lookupScalar, one ray per
// call) and the batched kernel (lookupBatch, all rays in one call), interleaved in one run so
// the batched/scalar ratio compares like with like on a shared machine.

#include "core/parallax/prepared_proxy.h"

#include <functional>
#include <optional>
#include <vector>

namespace probeproxy::cli {

// Rays in world metres as the shader sees them (float), one array per coordinate. Owned.
struct LookupRays {
  std::vector<float> x, y, z, dirX, dirY, dirZ;
  std::size_t size() const { return x.size(); }
};

struct TimingJob {
  const PreparedProxy* proxy = nullptr;  // not owned; outlives timeLookups
  const LookupRays* rays = nullptr;      // not owned; at least one ray
};

struct LookupTiming {
  std::optional<double> scalarNs;   // median over repetitions of CPU ns per lookup
  std::optional<double> batchedNs;  // the same for the batched kernel
};

struct TimingOptions {
  int repetitions = 5;           // medians are taken over these
  double minTimeSeconds = 0.01;  // per repetition; short: thousands of rays per iteration
};

// One timing per job, in job order. `onDone(done, total)` is called after each benchmark.
std::vector<LookupTiming> timeLookups(
    const std::vector<TimingJob>& jobs, const TimingOptions& options,
    const std::function<void(std::size_t, std::size_t)>& onDone = {});

}  // namespace probeproxy::cli
