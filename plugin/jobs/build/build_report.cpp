#include "plugin/jobs/build/build_report.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace probeproxy::jobs {

namespace {

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json errorJson(const ErrorFigures& e) {
  return {{"median_deg", number(e.medianDeg)},
          {"p95_deg", number(e.p95Deg)},
          {"max_deg", number(e.maxDeg)},
          {"miss_rate", number(e.missRate)},
          {"occluded_rate", number(e.occludedRate)},
          {"samples", e.samples}};
}

std::size_t vertexCount(const ProxyShape& shape) {
  if (const auto* convex = std::get_if<ConvexProxy>(&shape)) return convex->verticesMeters.size();
  return std::holds_alternative<BoxShape>(shape) ? 8 : 0;
}

std::string figure(double v, int precision) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << v;
  return s.str();
}

}  // namespace

std::string buildReportJson(const std::vector<ProbeProxyBuild>& builds) {
  nlohmann::json probes = nlohmann::json::array();
  for (const ProbeProxyBuild& b : builds) {
    const ProxyCandidate& kept = b.candidates[b.kept];
    nlohmann::json candidates = nlohmann::json::array();
    for (const ProxyCandidate& c : b.candidates) {
      candidates.push_back(
          {{"kind", candidateName(c)},
           {"method", std::string(methodId(c.shape))},
           {"planes", planeCount(c.shape)},
           {"error", errorJson(c.error)},
           {"error_all_surfaces", c.errorAllSurfaces.samples > 0 ? errorJson(c.errorAllSurfaces)
                                                                 : nlohmann::json(nullptr)},
           {"build_ms", c.buildMs}});
    }
    probes.push_back({{"name", b.probe},
                      {"proxy",
                       {{"kind", std::string(methodId(kept.shape))},
                        {"candidate", candidateName(kept)},
                        {"planes", planeCount(kept.shape)},
                        {"vertices", vertexCount(kept.shape)}}},
                      {"error", errorJson(kept.error)},
                      {"candidates", std::move(candidates)},
                      {"build_ms", b.buildMs},
                      {"build_ms_parts",
                       {{"depth", b.depthMs},
                        {"sampling", b.samplingMs},
                        {"hull", b.hullMs},
                        {"simplification", b.simplifyMs},
                        {"fits", b.fitMs},
                        {"evaluation", b.evaluateMs}}}});
  }
  return nlohmann::json{{"probes", std::move(probes)}}.dump(2) + "\n";
}

void printBuildTable(std::ostream& out, const std::vector<ProbeProxyBuild>& builds) {
  for (const ProbeProxyBuild& b : builds) {
    const ProxyCandidate& kept = b.candidates[b.kept];
    out << "probe " << b.probe << ": kept " << candidateName(kept) << " (" << methodId(kept.shape)
        << ", " << planeCount(kept.shape) << " planes), mirror_floor median "
        << figure(kept.error.medianDeg, 3) << " deg, p95 " << figure(kept.error.p95Deg, 3)
        << " deg, miss " << figure(100 * kept.error.missRate, 1) << "%, built in "
        << figure(b.buildMs, 1) << " ms\n";
    out << "  " << std::left << std::setw(12) << "candidate" << std::right << std::setw(7)
        << "planes" << std::setw(10) << "median" << std::setw(10) << "p95" << std::setw(10) << "max"
        << std::setw(8) << "miss%" << std::setw(10) << "occl%"
        << "\n";
    for (std::size_t i = 0; i < b.candidates.size(); ++i) {
      const ProxyCandidate& c = b.candidates[i];
      // The simplification gives a candidate per plane count; a person needs a few of them
      // (--json lists all).
      const int planes = planeCount(c.shape);
      const bool everyStep = c.origin == CandidateOrigin::Simplified;
      if (everyStep && i != b.kept && planes != 4 && planes != 6 && planes != 8 && planes % 8 != 0)
        continue;
      out << (i == b.kept ? "* " : "  ") << std::left << std::setw(12) << candidateName(c)
          << std::right << std::setw(7) << planeCount(c.shape) << std::setw(10)
          << figure(c.error.medianDeg, 3) << std::setw(10) << figure(c.error.p95Deg, 3)
          << std::setw(10) << figure(c.error.maxDeg, 2) << std::setw(8)
          << figure(100 * c.error.missRate, 1) << std::setw(10)
          << figure(100 * c.error.occludedRate, 1) << "\n";
    }
  }
}

}  // namespace probeproxy::jobs
