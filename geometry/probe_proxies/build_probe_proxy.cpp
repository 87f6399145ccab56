#include "geometry/probe_proxies/build_probe_proxy.h"

#include "core/errors/invariant_checks.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/fit/fit_error.h"
#include "geometry/fit/polytope_from_planes.h"
#include "geometry/probe_proxies/fit_candidates.h"
#include "geometry/probe_proxies/ieee_float_mode.h"
#include "geometry/probe_proxies/probe_samples.h"
#include "geometry/probe_proxies/probe_view.h"
#include "geometry/probe_proxies/select_proxy.h"
#include "geometry/probe_proxies/simplify_hull.h"
#include "geometry/probe_proxies/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace probeproxy {

namespace {

std::string noLevelFinding(double skyShare) {
  return "the capture point sees no level in " +
         std::to_string(static_cast<int>(std::round(100 * skyShare))) +
         "% of directions: it is outside the level, or the level is open";
}

// A capture point inside a wall sees the backs of the wall's faces; one inside a room whose
// faces all point outward (normals inverted on export) sees nothing else, and every fit then
// models the room's outside from within.
std::string backFacesFinding(double backShare) {
  return "the capture point sees the back of a surface in " +
         std::to_string(static_cast<int>(std::round(100 * backShare))) +
         "% of directions: it is inside a wall, or the level's faces point away from its rooms "
         "(inverted normals: flip them where the level is made)";
}

// all_surfaces for every kind of proxy and the kept one; the simplification's many steps are
// selected on mirror_floor and reported on it alone.
void measureOnAllSurfaces(ProbeProxyBuild& build, glm::dvec3 capture,
                          const std::vector<ReflectionSample>& all) {
  for (std::size_t i = 0; i < build.candidates.size(); ++i) {
    ProxyCandidate& c = build.candidates[i];
    if (i == build.kept || c.origin != CandidateOrigin::Simplified)
      c.errorAllSurfaces = evaluateShape(c.shape, capture, all);
  }
}

}  // namespace

// The simplification's reach rule samples directions (PlaneReach), and a wedge between two
// nearly parallel planes can slip between them: skyway's layout kept an 8 km wedge along a
// wall 0.2 degrees off another. Corners are exact; twice the rule's reach leaves room for a
// corner between sampled directions.
void dropStepsReachingFar(ProbeProxyBuild& build, glm::dvec3 capture, double farthestSeenMeters,
                          const ProxyBuildOptions& o) {
  PROBEPROXY_CHECK(build.kept < build.candidates.size());
  const double limit = 2 * kMaxReachOverFarthestSeen * farthestSeenMeters;
  while (build.candidates[build.kept].origin == CandidateOrigin::Simplified) {
    auto& convex = std::get<ConvexProxy>(build.candidates[build.kept].shape);
    try {
      ConvexProxy withCorners = polytopeFromPlanes(convex.planes, capture);
      if (farthestCornerMeters(withCorners, capture) <= limit) {
        convex = std::move(withCorners);
        return;
      }
    } catch (const FitError&) {
      return;  // finishKeptProxy says so and keeps the box
    }
    build.candidates.erase(build.candidates.begin() + static_cast<std::ptrdiff_t>(build.kept),
                           build.candidates.end());
    build.kept = selectProxy(build.candidates, o);
  }
}

void finishKeptProxy(ProbeProxyBuild& build, glm::dvec3 capture) {
  PROBEPROXY_CHECK(build.kept < build.candidates.size());
  if (auto* convex = std::get_if<ConvexProxy>(&build.candidates[build.kept].shape);
      convex != nullptr && convex->verticesMeters.empty()) {
    try {
      *convex = polytopeFromPlanes(convex->planes, capture);
      // Planes that bound no facet of their own are left out (so its name, convex_<planes>,
      // says what remains).
    } catch (const FitError& e) {
      // Without corners the runtime could not draw or load it: keep the fitted box instead.
      build.findings.push_back(std::string("the kept proxy has no boundary mesh, keeping the "
                                           "box instead: ") +
                               e.what());
      const auto box =
          std::find_if(build.candidates.begin(), build.candidates.end(),
                       [](const ProxyCandidate& c) { return c.origin == CandidateOrigin::Aabb; });
      build.kept = box == build.candidates.end()
                       ? 0
                       : static_cast<std::size_t>(box - build.candidates.begin());
    }
  }
  if (!strictlyContains(build.candidates[build.kept].shape, capture))
    build.findings.push_back("the capture point is not inside the kept proxy");
}

ProbeProxyBuild buildProbeProxy(const LevelRayCaster& level, const Probe& probe,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& o) {
  const Stopwatch depth;
  const ProbeView view = seeLevel(level, probe.captureMeters, o.depthFaceSize);
  const double depthMs = depth.ms();
  ProbeProxyBuild build = buildProbeProxy(level, probe, view, fitViewHull(view), authored, o);
  build.depthMs = depthMs;
  build.buildMs += depthMs;
  return build;
}

ProbeProxyBuild buildProbeProxy(const LevelRayCaster& level, const Probe& probe,
                                const ProbeView& view, const ViewHull& hull,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& o) {
  const IeeeFloatMode ieee;  // the samples' figures too
  const Stopwatch sampling;
  const ProbeSamples samples = drawProbeSamples(level, probe, o);
  const double samplingMs = sampling.ms();
  ProbeProxyBuild build = buildProbeProxy(probe, view, hull, samples, authored, o);
  build.samplingMs = samplingMs;
  build.buildMs += samplingMs;
  return build;
}

ProbeProxyBuild buildProbeProxy(const Probe& probe, const ProbeView& view, const ViewHull& hull,
                                const ProbeSamples& samples,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& o) {
  const IeeeFloatMode ieee;
  const Stopwatch total;
  ProbeProxyBuild build;
  build.probe = probe.name;
  const glm::dvec3 capture = probe.captureMeters;
  if (view.skyShare > 0.5) build.findings.push_back(noLevelFinding(view.skyShare));
  if (view.backShare > 0.5) build.findings.push_back(backFacesFinding(view.backShare));
  if (samples.floor.empty()) {
    build.findings.push_back(
        "no mirror_floor sample: the influence volume holds no upward surface the capture point "
        "sees, so no candidate is measured (a volume smaller than its room's floor, or lengths "
        "in other units than the level's?)");
  }

  Stopwatch stage;

  FittedCandidates fitted = fitCandidates(view, hull, samples.fit, authored, o.uprightObb);
  build.hullMs = fitted.hullMs;
  build.fitMs = fitted.fitMs;
  for (std::string& f : fitted.findings) build.findings.push_back(std::move(f));
  build.candidates = std::move(fitted.candidates);
  if (fitted.hull) {
    for (ProxyCandidate& c :
         simplifyHull(*fitted.hull, view, samples.fit, o.simplifyHoldingFloor, build.simplifyMs))
      build.candidates.push_back(std::move(c));
  }

  stage.lap();
  for (ProxyCandidate& c : build.candidates)
    c.error = evaluateShape(c.shape, capture, samples.floor);
  build.kept = selectProxy(build.candidates, o);
  dropStepsReachingFar(build, capture, view.farthestMeters, o);
  measureOnAllSurfaces(build, capture, samples.all);
  build.evaluateMs = stage.lap();
  finishKeptProxy(build, capture);
  if (std::string over = overToleranceFinding(build.candidates, build.kept, o); !over.empty())
    build.findings.push_back(std::move(over));
  build.buildMs = total.ms() + build.hullMs;
  return build;
}

}  // namespace probeproxy
