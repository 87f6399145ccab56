#pragma once
// `bench`: speed against accuracy of every correction method on levels (bench_scenes.h), the
// report written as bench.json (the charts' input, scripts/bench_charts.py) and the mirror
// views rebuilt with the infinite, authored and kept proxy.

#include "plugin/jobs/bench/bench_result.h"
#include "plugin/jobs/bench/bench_scenes.h"
#include "plugin/jobs/job_progress.h"

#include <filesystem>
#include <string>
#include <vector>

namespace probeproxy::jobs {

struct BenchJobOptions {
  std::vector<std::filesystem::path> scenes;
  std::filesystem::path outFolder;  // bench.json and images/; empty: nothing is written
  BenchOptions bench;

  // Throws InputError: no scene, repetitions outside [1, 100], min_time outside [0.001, 10] s,
  // or a proxy build option outside its range.
  void check() const;
};

struct BenchJobResult {
  std::vector<BenchResult> results;
  std::string json;                 // the `bench --json` report
  std::filesystem::path benchJson;  // written, or empty
};

BenchJobResult runBenchJob(const BenchJobOptions& options, const Say& say = {});

}  // namespace probeproxy::jobs
