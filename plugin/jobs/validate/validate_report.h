#pragma once
// What `probeproxy validate` prints: one block per finding for people, or the JSON of
// docs/methods_and_measures.md for tools.

#include "geometry/validate/validate_scene.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace probeproxy::jobs {

// {"findings": [{"probe", "rule", "severity", "value", "limit", "message", "hint"}]}; a value
// that is not finite is null.
std::string validateReportJson(const std::vector<ValidationFinding>& findings);

// A block per finding (severity, rule, probe, value / limit, message, hint), then a summary.
void printFindings(std::ostream& out, const std::string& scene,
                   const std::vector<ValidationFinding>& findings);

}  // namespace probeproxy::jobs
