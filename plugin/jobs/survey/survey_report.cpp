#include "plugin/jobs/survey/survey_report.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <ostream>

namespace probeproxy::jobs {

namespace {

nlohmann::ordered_json number(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

std::string surveyReportJson(const SurveyResult& r) {
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
  j["seconds"] = number(f.seconds);
  return j.dump(2) + "\n";
}

void printSurveyTable(std::ostream& out, const SurveyResult& r) {
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
  row("time                 ", "%.2f s", f.seconds);
}

}  // namespace probeproxy::jobs
