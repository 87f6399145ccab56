#include "plugin/jobs/validate/validate_report.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <ostream>

namespace probeproxy::jobs {

std::string validateReportJson(const std::vector<ValidationFinding>& findings) {
  nlohmann::json list = nlohmann::json::array();
  for (const ValidationFinding& f : findings) {
    auto number = [](double v) {
      return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
    };
    nlohmann::json item;  // insertion order is not kept; nlohmann sorts keys: stable bytes
    item["probe"] = f.probe;
    item["rule"] = f.rule;
    item["severity"] = f.severity;
    item["value"] = number(f.value);
    item["limit"] = number(f.limit);
    item["message"] = f.message;
    item["hint"] = f.hint;
    list.push_back(std::move(item));
  }
  return nlohmann::json{{"findings", std::move(list)}}.dump(2) + "\n";
}

void printFindings(std::ostream& out, const std::string& scene,
                   const std::vector<ValidationFinding>& findings) {
  int errors = 0, warnings = 0, infos = 0;
  for (const ValidationFinding& f : findings) {
    errors += f.severity == "error", warnings += f.severity == "warning",
        infos += f.severity == "info";
    out << std::left << std::setw(8) << f.severity << f.rule << "  probe '" << f.probe
        << "'  value " << std::setprecision(4) << f.value << " / limit " << f.limit << "\n"
        << "        " << f.message << "\n"
        << "        hint: " << f.hint << "\n";
  }
  if (findings.empty()) {
    out << scene << ": clean, no findings\n";
  } else {
    out << scene << ": " << findings.size() << " finding" << (findings.size() == 1 ? "" : "s")
        << " (" << errors << " error, " << warnings << " warning, " << infos << " info)\n";
  }
}

}  // namespace probeproxy::jobs
