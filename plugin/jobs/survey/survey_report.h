#pragma once
// `survey --json`: the report of docs/methods_and_measures.md, {"scene", "walkable_m2", "samples",
// "probes", "median_deg", "p95_deg", "over_tolerance_share", "uncovered_share", "occluded_share",
// "seconds"} in that order; a figure with no value (no visible floor) is null. And the table
// for people.

#include "geometry/survey/survey_result.h"

#include <iosfwd>
#include <string>

namespace probeproxy::jobs {

std::string surveyReportJson(const SurveyResult& result);

void printSurveyTable(std::ostream& out, const SurveyResult& result);

}  // namespace probeproxy::jobs
