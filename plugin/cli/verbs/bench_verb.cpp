#include "core/io/atomic_write.h"
#include "plugin/cli/bench/bench_report.h"
#include "plugin/cli/bench/bench_scenes.h"
#include "plugin/cli/verb.h"

#include <unistd.h>
#include <filesystem>
#include <iostream>
#include <memory>

namespace probeproxy::cli {

namespace {

struct BenchVerbOptions {
  std::vector<std::string> scenes;
  std::string out;
  bool json = false;
  BenchOptions bench;
};

int runBench(const BenchVerbOptions& o) {
  BenchOptions bench = o.bench;
  if (!o.out.empty()) bench.imagesFolder = std::filesystem::path(o.out) / "images";
  const std::vector<BenchResult> results = benchScenes(o.scenes, bench, [](std::string_view line) {
    std::cerr << "probeproxy bench: " << line << "\n";
  });
  const std::string json = benchReportJson(results);
  if (!o.out.empty()) {
    std::filesystem::create_directories(o.out);
    const std::filesystem::path file = std::filesystem::path(o.out) / "bench.json";
    writeFileAtomically(file, json);
    std::cerr << "probeproxy bench: wrote " << file.string()
              << " (charts: python3 scripts/bench_charts.py " << file.string() << " " << o.out
              << ")\n";
  }
  if (o.json) {
    std::cout << json;
  } else {
    printBenchTable(std::cout, results);
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
      ->add_option("--repetitions", o->bench.timing.repetitions,
                   "timing repetitions; ns per lookup is their median")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  bench
      ->add_option("--min-time", o->bench.timing.minTimeSeconds,
                   "CPU seconds each timing repetition runs at least")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 10.0));
  bench
      ->add_option("--samples", o->bench.proxy.samples.targetSamples,
                   "reflection samples per set (the error figures and the timed rays)")
      ->capture_default_str()
      ->check(CLI::Range(64, 1000000));
  bench->add_flag("!--no-instructions", o->bench.countInstructions,
                  "skip instructions per lookup (callgrind); they are reported as null");
  return {bench, [o] { return runBench(*o); }};
}

}  // namespace probeproxy::cli
