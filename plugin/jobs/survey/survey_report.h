#pragma once
// `survey --json`: the report of docs/methods_and_measures.md, {"scene", "walkable_m2", "samples",
// "probes", "median_deg", "p95_deg", "over_tolerance_share", "uncovered_share", "occluded_share",
// "worst_floor", "seconds"} in that order; a figure with no value (no visible floor) is null.
// And the table for people. `probes` are the surveyed scene's, which the worst floor's probe
// indices refer to.

#include "core/scene/scene.h"
#include "geometry/survey/survey_result.h"

#include <iosfwd>
#include <span>
#include <string>

namespace probeproxy::jobs {

// The worst floor's probes the report names, the largest shares first.
inline constexpr std::size_t kWorstFloorProbesReported = 5;

std::string surveyReportJson(const SurveyResult& result, std::span<const Probe> probes);

void printSurveyTable(std::ostream& out, const SurveyResult& result, std::span<const Probe> probes);

}  // namespace probeproxy::jobs
