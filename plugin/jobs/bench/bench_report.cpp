#include "plugin/jobs/bench/bench_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace probeproxy::jobs {

namespace {

nlohmann::json number(std::optional<double> v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::optional<double> speedup(const BenchResult& r) {
  if (!r.nsPerLookup || !r.nsPerLookupScalar || *r.nsPerLookup <= 0) return std::nullopt;
  return *r.nsPerLookupScalar / *r.nsPerLookup;
}

// NaN prints as "-", as a missing figure does.
std::string figure(double v, int precision) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << v;
  return s.str();
}

std::string figure(std::optional<double> v, int precision) {
  return figure(v.value_or(std::nan("")), precision);
}

}  // namespace

std::string benchReportJson(const std::vector<BenchResult>& results) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const BenchResult& r : results) {
    nlohmann::ordered_json row;
    row["scene"] = r.scene;
    row["method"] = r.method;
    row["planes"] = r.planes;
    row["ns_per_lookup"] = number(r.nsPerLookup);
    row["instructions_per_lookup"] = number(r.instructionsPerLookup);
    row["median_deg"] = number(r.error.medianDeg);
    row["p95_deg"] = number(r.error.p95Deg);
    row["miss_rate"] = number(r.error.missRate);
    row["psnr_db"] = number(r.psnrDb);
    row["probe"] = r.probe;
    row["candidate"] = r.candidate;
    row["kept"] = r.kept;
    row["ns_per_lookup_scalar"] = number(r.nsPerLookupScalar);
    row["batched_speedup"] = number(speedup(r));
    row["max_deg"] = number(r.error.maxDeg);
    row["occluded_rate"] = number(r.error.occludedRate);
    row["samples"] = r.error.samples;
    rows.push_back(std::move(row));
  }
  nlohmann::ordered_json report;
  report["results"] = std::move(rows);
  return report.dump(2) + "\n";
}

void printBenchTable(std::ostream& out, const std::vector<BenchResult>& results) {
  // The name columns as wide as their longest entry and a space, so no name runs into the next.
  std::size_t sceneW = 6, probeW = 6, candidateW = 10, methodW = 7;
  for (const BenchResult& r : results) {
    sceneW = std::max(sceneW, r.scene.size() + 1);
    probeW = std::max(probeW, r.probe.size() + 1);
    candidateW = std::max(candidateW, r.candidate.size() + 2);  // and the kept mark
    methodW = std::max(methodW, r.method.size() + 1);
  }
  const auto w = [](std::size_t width) { return std::setw(static_cast<int>(width)); };
  out << std::left << w(sceneW) << "scene" << w(probeW) << "probe" << w(candidateW) << "candidate"
      << w(methodW) << "method" << std::right << std::setw(7) << "planes" << std::setw(10)
      << "ns batch" << std::setw(10) << "ns scalar" << std::setw(8) << "ratio" << std::setw(8)
      << "instr" << std::setw(10) << "median" << std::setw(10) << "p95" << std::setw(8) << "miss %"
      << std::setw(8) << "psnr"
      << "\n";
  for (const BenchResult& r : results) {
    const double missPercent = 100 * r.error.missRate;
    out << std::left << w(sceneW) << r.scene << w(probeW) << r.probe << w(candidateW)
        << (r.candidate + (r.kept ? "*" : "")) << w(methodW) << r.method << std::right
        << std::setw(7) << r.planes << std::setw(10) << figure(r.nsPerLookup, 2) << std::setw(10)
        << figure(r.nsPerLookupScalar, 2) << std::setw(8) << figure(speedup(r), 1) << std::setw(8)
        << figure(r.instructionsPerLookup, 1) << std::setw(10) << figure(r.error.medianDeg, 3)
        << std::setw(10) << figure(r.error.p95Deg, 3) << std::setw(8) << figure(missPercent, 1)
        << std::setw(8) << figure(r.psnrDb, 1) << "\n";
  }
  out << "ns: median CPU time per lookup (Google Benchmark) on the probe's mirror_floor rays; "
         "ratio = scalar / batched, same run; errors in degrees on mirror_floor; * = kept by "
         "`build`\n";
}

}  // namespace probeproxy::jobs
