#pragma once
// What `probeproxy build` prints: a table for people, or the JSON of docs/methods_and_measures.md
// for tools.

#include "core/proxy/proxy_candidate.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace probeproxy::jobs {

// {"probes": [{"name", "proxy": {"kind", "planes", "vertices"}, "error": {...}, "candidates":
// [{"kind", "planes", "error": {...}, "build_ms"}], "build_ms"}]}; figures not measured are null.
std::string buildReportJson(const std::vector<ProbeProxyBuild>& builds);

void printBuildTable(std::ostream& out, const std::vector<ProbeProxyBuild>& builds);

}  // namespace probeproxy::jobs
