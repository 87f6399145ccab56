#include "plugin/jobs/survey/survey_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace probeproxy::jobs {

namespace {

nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

std::string probeName(std::span<const Probe> probes, int probe) {
  const auto i = static_cast<std::size_t>(probe);
  return i < probes.size() ? probes[i].name : "probe " + std::to_string(probe);
}

nlohmann::ordered_json worstFloorJson(const WorstFloor& w, std::span<const Probe> probes) {
  nlohmann::ordered_json j;
  j["threshold_deg"] = number(w.thresholdDeg);
  j["m2"] = w.squareMeters;
  j["sky_share"] = w.skyShare;
  j["near_hit_share"] = w.nearHitShare;
  j["hit_inside_proxy_share"] = w.hitInsideProxyShare;
  j["probes"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < std::min(w.probes.size(), kWorstFloorProbesReported); ++i)
    j["probes"].push_back(
        {{"name", probeName(probes, w.probes[i].probe)}, {"share", w.probes[i].share}});
  return j;
}

}  // namespace

std::string surveyReportJson(const SurveyResult& r, std::span<const Probe> probes) {
  const SurveyFigures& f = r.figures;
  nlohmann::ordered_json j;
  j["scene"] = r.scene;
  j["engine"] = std::string(engineName(r.engine));
  j["walkable_m2"] = number(f.walkableSquareMeters);
  j["samples"] = f.samples;
  j["probes"] = f.probes;
  j["median_deg"] = number(f.medianDeg);
  j["p95_deg"] = number(f.p95Deg);
  j["over_tolerance_share"] = number(f.overToleranceShare);
  j["uncovered_share"] = number(f.uncoveredShare);
  j["occluded_share"] = number(f.occludedShare);
  j["worst_floor"] = worstFloorJson(r.worst, probes);
  j["seconds"] = number(f.seconds);
  return j.dump(2) + "\n";
}

void printSurveyTable(std::ostream& out, const SurveyResult& r, std::span<const Probe> probes) {
  const SurveyFigures& f = r.figures;
  char line[160];
  auto row = [&](const char* name, const char* format, double value) {
    std::snprintf(line, sizeof line, format, value);
    out << "  " << name << line << "\n";
  };
  out << "survey of " << r.scene << " (engine " << engineName(r.engine) << ")\n";
  row("walkable floor       ", "%.1f m^2", f.walkableSquareMeters);
  row("floor samples        ", "%.0f", static_cast<double>(f.samples));
  row("probes               ", "%.0f", static_cast<double>(f.probes));
  row("median error         ", "%.3f deg", f.medianDeg);
  row("p95 error            ", "%.3f deg", f.p95Deg);
  std::snprintf(line, sizeof line, "%.1f%% (over %.2f deg)", 100.0 * f.overToleranceShare,
                r.toleranceDeg);
  out << "  over tolerance       " << line << "\n";
  row("uncovered floor      ", "%.1f%%", 100.0 * f.uncoveredShare);
  row("occluded             ", "%.1f%%", 100.0 * f.occludedShare);
  const WorstFloor& w = r.worst;
  if (w.squareMeters > 0.0) {
    std::snprintf(line, sizeof line,
                  "%.1f m^2 at %.2f deg or over: %.0f%% sky, %.0f%% hits within %.0f m, %.0f%% "
                  "hits inside the proxy",
                  w.squareMeters, w.thresholdDeg, 100.0 * w.skyShare, 100.0 * w.nearHitShare,
                  kNearHitMeters, 100.0 * w.hitInsideProxyShare);
    out << "  worst 5% of floor    " << line << "\n";
    for (std::size_t i = 0; i < std::min(w.probes.size(), kWorstFloorProbesReported); ++i) {
      std::snprintf(line, sizeof line, "%.0f%% %s", 100.0 * w.probes[i].share,
                    probeName(probes, w.probes[i].probe).c_str());
      out << "                       " << line << "\n";
    }
  }
  row("time                 ", "%.2f s", f.seconds);
}

}  // namespace probeproxy::jobs
