#include "geometry/build/build_probe_proxy.h"

#include "geometry/build/ieee_float_mode.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/fit/bounding_sphere_fit.h"
#include "geometry/fit/convex_hull_proxy.h"
#include "geometry/fit/fit_error.h"
#include "geometry/fit/oriented_box_fit.h"
#include "geometry/fit/polytope_from_planes.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/tune/greedy_plane_removal.h"
#include "geometry/tune/one_dimensional_fits.h"
#include "geometry/tune/snap_box_to_walls.h"
#include "geometry/tune/visible_surface_planes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <tuple>

namespace probeproxy {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// What the probe sees: the level points of its depth cube (sky texels have none).
std::vector<glm::dvec3> seenPoints(const DepthCube& cube) {
  std::vector<glm::dvec3> points;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int row = 0; row < cube.faceSize; ++row) {
      for (int col = 0; col < cube.faceSize; ++col) {
        const float t = cube.at(CubeFace(f), col, row);
        if (std::isfinite(t)) {
          points.push_back(cube.captureMeters +
                           double(t) *
                               glm::dvec3(texelDirection(CubeFace(f), col, row, cube.faceSize)));
        }
      }
    }
  }
  return points;
}

// Shaders pay per plane; among equal plane counts the simpler test wins.
int methodRank(const ProxyShape& shape) {
  const std::string_view id = methodId(shape);
  static constexpr std::string_view order[] = {"infinite", "cheap_k", "sphere",
                                               "aabb",     "obb",     "convex"};
  return static_cast<int>(std::find(std::begin(order), std::end(order), id) - std::begin(order));
}

bool meetsTolerance(const ErrorFigures& e, const ProxyBuildOptions& o) {
  return std::isfinite(e.p95Deg) && e.p95Deg <= o.toleranceDeg && e.missRate <= o.maxMissRate;
}

}  // namespace

std::size_t selectProxy(const std::vector<ProxyCandidate>& candidates, const ProxyBuildOptions& o) {
  if (!o.regenerate && !candidates.empty() && candidates.front().kind == "authored") return 0;
  const auto complexity = [&](std::size_t i) {
    return std::make_tuple(planeCount(candidates[i].shape), methodRank(candidates[i].shape), i);
  };
  // The fewest planes that meet the tolerance.
  std::size_t best = candidates.size();
  const auto generated = [&](std::size_t i) {
    return candidates[i].kind != "authored" && planeCount(candidates[i].shape) <= o.maxPlanes;
  };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || !meetsTolerance(candidates[i].error, o)) continue;
    if (best == candidates.size() || complexity(i) < complexity(best)) best = i;
  }
  if (best != candidates.size()) return best;
  // None does: the most accurate within the plane budget, by mean error (misses at 180
  // degrees), sparing the planes that buy less than 5% of it: a concave room that no convex
  // proxy models gets a simple proxy, not 30 planes for a hundredth of a degree.
  const auto meanOf = [&](std::size_t i) {
    const double m = candidates[i].error.meanCostDeg;
    return std::isfinite(m) ? m : 1e300;
  };
  std::size_t mostAccurate = candidates.size();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || candidates[i].error.missRate > o.maxMissRate) continue;
    if (mostAccurate == candidates.size() || meanOf(i) < meanOf(mostAccurate)) mostAccurate = i;
  }
  if (mostAccurate == candidates.size()) return 0;  // nothing but misses: keep the first
  const double goodEnough = 1.05 * meanOf(mostAccurate) + 0.01;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!generated(i) || candidates[i].error.missRate > o.maxMissRate || meanOf(i) > goodEnough)
      continue;
    if (best == candidates.size() || complexity(i) < complexity(best)) best = i;
  }
  return best;
}

ProbeProxyBuild buildProbeProxy(const LevelRayCaster& level, const Probe& probe,
                                const std::optional<ProxyShape>& authored,
                                const ProxyBuildOptions& o) {
  const IeeeFloatMode ieee;
  const auto start = Clock::now();
  ProbeProxyBuild build;
  build.probe = probe.name;
  const glm::dvec3 capture = probe.captureMeters;

  auto t = Clock::now();
  const std::vector<RayHit> hits = castDepthCubeRays(level, capture, o.depthFaceSize);
  const std::vector<glm::dvec3> points =
      seenPoints(depthCubeFromHits(hits, capture, o.depthFaceSize));
  build.depthMs = msSince(t);
  const double skyShare =
      1.0 - static_cast<double>(points.size()) / static_cast<double>(hits.size());
  if (skyShare > 0.5) {
    build.findings.push_back("the capture point sees no level in " +
                             std::to_string(static_cast<int>(std::round(100 * skyShare))) +
                             "% of directions: it is outside the level, or the level is open");
  }

  // Fit on one sample set and report on others drawn with other seeds, so the figures are not
  // flattered by fitting to the very samples they are measured on.
  t = Clock::now();
  const ReflectionSampleOptions& fitOptions = o.samples;
  ReflectionSampleOptions reportOptions = o.samples;
  reportOptions.seed = o.samples.seed + 1000;
  // Fitting sees every surface, not just floors: a proxy tuned to floor reflections alone
  // would drop walls that floor reflections happen not to reach.
  std::vector<ReflectionSample> fitSamples =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor, fitOptions);
  for (const ReflectionSample& s :
       buildReflectionSamples(level, probe, SampleSet::AllSurfaces, fitOptions)) {
    fitSamples.push_back(s);
  }
  const auto floorSamples =
      buildReflectionSamples(level, probe, SampleSet::MirrorFloor, reportOptions);
  const auto allSamples =
      buildReflectionSamples(level, probe, SampleSet::AllSurfaces, reportOptions);
  build.samplingMs = msSince(t);

  std::vector<ProxyCandidate> candidates;
  const auto add = [&](std::string kind, ProxyShape shape, double buildMs) {
    candidates.push_back({std::move(kind), std::move(shape), {}, {}, buildMs});
  };
  if (authored) add("authored", *authored, 0.0);

  double nearest = 1e300, farthest = 0.0;
  for (const glm::dvec3& p : points) {
    const double d = glm::distance(p, capture);
    nearest = std::min(nearest, d), farthest = std::max(farthest, d);
  }
  if (points.empty()) nearest = farthest = 1.0;

  // The hull of what the probe sees comes first: boxes and spheres around the points are
  // boxes and spheres around the hull's corners, a few hundred points instead of 10^5.
  std::optional<ConvexProxy> hull;
  double tolerance = 1e-4;
  try {
    t = Clock::now();
    tolerance = 1e-4 * std::max(farthest, 1e-3) + 1e-4;
    hull = convexHullProxy(points, tolerance);
    build.hullMs = msSince(t);
    if (signedDistanceOutside(hull->planes, capture) >= 0) {
      hull.reset();
      throw FitError("the capture point is outside everything it sees: it is outside the level");
    }
  } catch (const FitError& e) {
    // A probe that sees one plane only (or nothing) gets no hull; the other candidates stand.
    build.findings.push_back(std::string("no convex proxy: ") + e.what());
  }
  const std::span<const glm::dvec3> corners =
      hull ? std::span<const glm::dvec3>(hull->verticesMeters)
           : std::span<const glm::dvec3>(points);

  // The planes of the walls the probe sees, exact where the hull's facets tilt by a texel.
  const std::vector<ProxyPlane> walls =
      visibleSurfacePlanes(hits, capture, o.depthFaceSize, 10 * tolerance);

  t = Clock::now();
  add("infinite", InfiniteShape{}, 0.0);
  // One free parameter needs far fewer samples than a plane set: every fourth will do.
  std::vector<ReflectionSample> sparseFitSamples;
  for (std::size_t i = 0; i < fitSamples.size(); i += 4) sparseFitSamples.push_back(fitSamples[i]);
  auto fitStart = Clock::now();
  add("cheap_k", fitCheapK(capture, sparseFitSamples, 0.5 * (nearest + farthest)),
      msSince(fitStart));
  fitStart = Clock::now();
  add("sphere", fitCaptureSphere(capture, sparseFitSamples, nearest, farthest), msSince(fitStart));
  if (!corners.empty()) {
    fitStart = Clock::now();
    add("min_sphere", minimumEnclosingSphere(corners), msSince(fitStart));
    fitStart = Clock::now();
    add("aabb", snapBoxToWalls(axisAlignedBoxFit(corners), walls, 10 * tolerance),
        msSince(fitStart));
    fitStart = Clock::now();
    add("obb", snapBoxToWalls(orientedBoxFit(corners), walls, 10 * tolerance), msSince(fitStart));
  }
  build.fitMs = msSince(t);

  if (hull) {
    add("hull", *hull, build.hullMs);
    // Every simplification of the hull's planes and of the planes of the walls the probe sees
    // (the inner walls of a concave room among them), down to a tetrahedron; error decides
    // which planes stay.
    t = Clock::now();
    // The hull has a thin bevel plane wherever two walls meet between texels; they cost no
    // accuracy and only slow the simplification, so planes under 0.2% of the hull's area start
    // out dropped (kept if the rest would not be bounded).
    std::vector<ProxyPlane> planes;
    const std::vector<double> areas = planeAreasSquareMeters(*hull);
    const double totalArea = std::accumulate(areas.begin(), areas.end(), 0.0);
    for (std::size_t i = 0; i < hull->planes.size(); ++i) {
      if (areas[i] >= 0.002 * totalArea) planes.push_back(hull->planes[i]);
    }
    if (!isBounded(planes)) planes = hull->planes;
    // A hull facet on a wall passes through three texel hits and tilts by up to a texel's
    // angle; the wall's own plane (every texel on it averaged) is exact. So a wall plane
    // replaces the hull facets it matches, and the proxy's walls coincide with the level's.
    for (const ProxyPlane& p : walls) {
      const auto matches = [&](const ProxyPlane& q) {
        return glm::dot(p.normal, q.normal) > 0.9998 &&
               std::abs(p.offsetMeters - q.offsetMeters) < 10 * tolerance;
      };
      const std::vector<ProxyPlane> before = planes;
      std::erase_if(planes, matches);
      planes.push_back(p);
      if (!isBounded(planes)) planes = before;
    }
    // A proxy may reach past what the probe sees (an open end of a corridor), but not far:
    // twice the farthest point seen.
    const auto acceptable = [&](const std::vector<ProxyPlane>& p) {
      return isBounded(p) && farthestExitMeters(p, capture) <= 2.0 * farthest;
    };
    const std::vector<PlaneRemovalStep> steps =
        greedyPlaneRemoval(planes, capture, fitSamples, 4, acceptable);
    build.simplifyMs = msSince(t);
    const double perStepMs = steps.size() > 1 ? build.simplifyMs / double(steps.size() - 1) : 0.0;
    for (std::size_t s = 1; s < steps.size(); ++s) {
      ConvexProxy simplified;
      simplified.planes = steps[s].planes;
      add("convex_" + std::to_string(steps[s].planes.size()), std::move(simplified),
          perStepMs * double(s));
    }
  }

  t = Clock::now();
  for (ProxyCandidate& c : candidates) c.error = evaluateShape(c.shape, capture, floorSamples);
  build.candidates = std::move(candidates);
  build.kept = selectProxy(build.candidates, o);
  // all_surfaces for every kind of proxy and the kept one; the simplification's many steps
  // are selected on mirror_floor and reported on it alone.
  for (std::size_t i = 0; i < build.candidates.size(); ++i) {
    ProxyCandidate& c = build.candidates[i];
    if (i == build.kept || c.kind.rfind("convex_", 0) != 0) {
      c.errorAllSurfaces = evaluateShape(c.shape, capture, allSamples);
    }
  }
  build.evaluateMs = msSince(t);
  // Only the kept simplification needs its corners: engines and Blender draw it.
  if (auto* convex = std::get_if<ConvexProxy>(&build.candidates[build.kept].shape);
      convex != nullptr && convex->verticesMeters.empty()) {
    try {
      *convex = polytopeFromPlanes(convex->planes, capture);
    } catch (const FitError& e) {
      // Without corners the runtime could not draw or load it: keep the fitted box instead.
      build.findings.push_back(std::string("the kept proxy has no boundary mesh, keeping the "
                                           "box instead: ") +
                               e.what());
      const auto box = std::find_if(build.candidates.begin(), build.candidates.end(),
                                    [](const ProxyCandidate& c) { return c.kind == "aabb"; });
      build.kept = box == build.candidates.end()
                       ? 0
                       : static_cast<std::size_t>(box - build.candidates.begin());
    }
  }
  if (!strictlyContains(build.candidates[build.kept].shape, capture)) {
    build.findings.push_back("the capture point is not inside the kept proxy");
  }
  build.buildMs = msSince(start);
  return build;
}

}  // namespace probeproxy
