#pragma once
// What `probeproxy bench` prints: a table for people, or the JSON of docs/methods_and_measures.md
// for tools:
// {"results": [{"scene", "method", "planes", "ns_per_lookup", "instructions_per_lookup",
// "median_deg", "p95_deg", "miss_rate", "psnr_db", then "probe", "candidate", "kept",
// "ns_per_lookup_scalar", "batched_speedup", "max_deg", "occluded_rate", "samples"}]};
// a figure not measured is null.

#include "plugin/jobs/bench/bench_result.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace probeproxy::jobs {

std::string benchReportJson(const std::vector<BenchResult>& results);

void printBenchTable(std::ostream& out, const std::vector<BenchResult>& results);

}  // namespace probeproxy::jobs
