// `probeproxy bench`: flags into the bench job (plugin/jobs/bench/), its table or JSON printed.

#include "plugin/cli/verb.h"
#include "plugin/jobs/bench/bench_job.h"
#include "plugin/jobs/bench/bench_report.h"

#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct BenchVerbOptions {
  std::vector<std::string> scenes;
  std::string out;
  bool json = false;
  jobs::BenchJobOptions job;
};

int runBench(BenchVerbOptions o) {
  o.job.scenes.assign(o.scenes.begin(), o.scenes.end());
  o.job.outFolder = o.out;
  const jobs::BenchJobResult r = jobs::runBenchJob(
      o.job, [](std::string_view line) { std::cerr << "probeproxy bench: " << line << "\n"; });
  if (!r.benchJson.empty()) {
    std::cerr << "probeproxy bench: wrote " << r.benchJson.string()
              << " (charts: python3 scripts/bench_charts.py " << r.benchJson.string() << " "
              << o.out << ")\n";
  }
  if (o.json) {
    std::cout << r.json;
  } else {
    jobs::printBenchTable(std::cout, r.results);
  }
  return 0;
}

}  // namespace

Verb addBenchVerb(CLI::App& app) {
  auto o = std::make_shared<BenchVerbOptions>();
  CLI::App* bench = app.add_subcommand(
      "bench", "Measure speed against accuracy of every correction method on levels");
  bench->add_option("scenes", o->scenes, "scene files (*.scene.json)")->required();
  bench->add_flag("--json", o->json, "print the results as JSON on stdout");
  bench->add_option("--out", o->out,
                    "folder for bench.json (the charts' input) and images/: each mirror view "
                    "rebuilt with the infinite, authored and kept proxy (error heatmap, red miss "
                    "mask, EXR)");
  bench
      ->add_option("--repetitions", o->job.bench.timing.repetitions,
                   "timing repetitions; ns per lookup is their median")
      ->capture_default_str();
  bench
      ->add_option("--min-time", o->job.bench.timing.minTimeSeconds,
                   "CPU seconds each timing repetition runs at least")
      ->capture_default_str();
  bench
      ->add_option("--samples", o->job.bench.proxy.samples.targetSamples,
                   "reflection samples per set (the error figures and the timed rays)")
      ->capture_default_str();
  bench->add_flag("!--no-instructions", o->job.bench.countInstructions,
                  "skip instructions per lookup (callgrind); they are reported as null");
  return {bench, [o] { return runBench(*o); }};
}

}  // namespace probeproxy::cli
