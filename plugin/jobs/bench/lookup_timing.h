#pragma once
// ns per lookup of prepared proxies, measured with Google Benchmark inside the CLI: each
// proxy is timed on the same rays through the scalar seed-code port (lookupScalar, one ray per
// call) and the batched kernel (lookupBatch, all rays in one call), interleaved in one run so
// the batched/scalar ratio compares like with like on a shared machine.

#include "core/parallax/prepared_proxy.h"

#include <functional>
#include <optional>
#include <vector>

namespace probeproxy::jobs {

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

// Work that is not a per-ray lookup (a corrected cubemap, a point-cloud splat), timed the same
// way and reported per item of it.
struct CallJob {
  std::function<void()> call;  // one unit of work; safe to repeat
  double itemsPerCall = 1.0;   // what the ns are per: texels corrected, shading points
};

struct TimingOptions {
  int repetitions = 3;            // medians are taken over these
  double minTimeSeconds = 0.005;  // per repetition, CPU; hundreds of iterations of 2048 rays
};

// Keeps the compiler from dropping work whose result a call job does not use
// (benchmark::DoNotOptimize on the bytes at `result`).
void keepResult(const void* result);

struct Timings {
  std::vector<LookupTiming> lookups;             // one per TimingJob, in order
  std::vector<std::optional<double>> nsPerItem;  // one per CallJob, in order: median CPU ns
};

// Every lookup job (scalar then batched) and every call job, in one run. `onDone(done, total)`
// is called after each benchmark.
Timings timeBenchmarks(const std::vector<TimingJob>& jobs, const std::vector<CallJob>& calls,
                       const TimingOptions& options,
                       const std::function<void(std::size_t, std::size_t)>& onDone = {});

}  // namespace probeproxy::jobs
