#include "plugin/jobs/bench/bench_job.h"

#include "core/errors/input_error.h"
#include "core/errors/option_checks.h"
#include "core/io/atomic_write.h"
#include "core/io/output_folder.h"
#include "plugin/jobs/bench/bench_report.h"

namespace probeproxy::jobs {

void BenchJobOptions::check() const {
  if (scenes.empty()) throw InputError("bench", "no scene file given");
  requireInRange("repetitions", bench.timing.repetitions, 1, 100);
  requireInRange("min_time", bench.timing.minTimeSeconds, 0.001, 10.0);
  bench.proxy.check();
  if (!outFolder.empty()) checkOutputFolder(outFolder);
}

BenchJobResult runBenchJob(const BenchJobOptions& o, const Say& say) {
  o.check();
  BenchOptions bench = o.bench;
  if (!o.outFolder.empty()) bench.imagesFolder = o.outFolder / "images";
  std::vector<std::string> scenes;
  for (const std::filesystem::path& s : o.scenes) scenes.push_back(s.string());
  BenchJobResult result;
  result.results = benchScenes(scenes, bench, say);
  result.json = benchReportJson(result.results);
  if (!o.outFolder.empty()) {
    std::filesystem::create_directories(o.outFolder);
    result.benchJson = o.outFolder / "bench.json";
    writeFileAtomically(result.benchJson, result.json);
  }
  return result;
}

}  // namespace probeproxy::jobs
