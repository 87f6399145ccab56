#include "geometry/probe_proxies/fit_candidates.h"

#include "geometry/fit/bounding_sphere_fit.h"
#include "geometry/fit/convex_hull_proxy.h"
#include "geometry/fit/fit_error.h"
#include "geometry/fit/oriented_box_fit.h"
#include "geometry/fit/polytope_from_planes.h"
#include "geometry/probe_proxies/hold_shading_points.h"
#include "geometry/probe_proxies/room_box.h"
#include "geometry/probe_proxies/stopwatch.h"
#include "geometry/tune/one_dimensional_fits.h"
#include "geometry/tune/snap_box_to_walls.h"

#include <algorithm>
#include <cmath>

namespace probeproxy {

ViewHull fitViewHull(const ProbeView& view) {
  // Boxes and spheres around the points are boxes and spheres around the hull's corners: a few
  // hundred points instead of 10^5.
  ViewHull h;
  try {
    const Stopwatch hullTime;
    h.hull = convexHullProxy(view.pointsMeters, view.toleranceMeters);
    h.hullMs = hullTime.ms();
    if (signedDistanceOutside(h.hull->planes, view.captureMeters) >= 0) {
      h.hull.reset();
      throw FitError("the capture point is outside everything it sees: it is outside the level");
    }
  } catch (const FitError& e) {
    // A probe that sees one plane only (or nothing) gets no hull; the other candidates stand.
    h.finding = std::string("no convex proxy: ") + e.what();
  }
  return h;
}

FittedCandidates fitCandidates(const ProbeView& view, std::span<const ReflectionSample> fitSamples,
                               const std::optional<ProxyShape>& authored, bool uprightObb) {
  return fitCandidates(view, fitViewHull(view), fitSamples, authored, uprightObb);
}

FittedCandidates fitCandidates(const ProbeView& view, const ViewHull& hull,
                               std::span<const ReflectionSample> fitSamples,
                               const std::optional<ProxyShape>& authored, bool uprightObb) {
  FittedCandidates f;
  const glm::dvec3 capture = view.captureMeters;
  const auto add = [&](CandidateOrigin origin, ProxyShape shape, double buildMs) {
    ProxyCandidate candidate{origin, std::move(shape), {}, {}, buildMs};
    // Fitted to points in one plane (a capture point that sees one wall, from outside), a box
    // or sphere is flat: it holds no volume, a lookup in it divides by zero and no engine
    // takes it.
    if (!holdsVolume(candidate.shape)) {
      if (origin == CandidateOrigin::Authored) {
        // Measured as authored, but no engine gets a box without a volume (runtime export).
        f.findings.push_back("the authored proxy is thinner than " +
                             std::to_string(int(kThinnestShapeMeters * 1000)) +
                             " mm on some axis: it holds no volume, and no engine preset is "
                             "made from it");
      } else {
        f.findings.push_back(candidateName(candidate) +
                             ": what it was fitted to lies in one plane, so it holds no volume");
        return;
      }
    }
    f.candidates.push_back(std::move(candidate));
  };
  if (authored) add(CandidateOrigin::Authored, *authored, 0.0);
  f.hull = hull.hull;
  f.hullMs = hull.hullMs;
  if (hull.finding) f.findings.push_back(*hull.finding);
  const std::span<const glm::dvec3> corners =
      f.hull ? std::span<const glm::dvec3>(f.hull->verticesMeters)
             : std::span<const glm::dvec3>(view.pointsMeters);
  const double snapMeters = 10 * view.toleranceMeters;

  const Stopwatch fitTime;
  add(CandidateOrigin::Infinite, InfiniteShape{}, 0.0);
  // One free parameter needs far fewer samples than a plane set: every fourth will do.
  std::vector<ReflectionSample> sparse;
  for (std::size_t i = 0; i < fitSamples.size(); i += 4) sparse.push_back(fitSamples[i]);
  Stopwatch each;
  add(CandidateOrigin::CheapK,
      fitCheapK(capture, sparse, 0.5 * (view.nearestMeters + view.farthestMeters)), each.lap());
  add(CandidateOrigin::Sphere,
      fitCaptureSphere(capture, sparse, view.nearestMeters, view.farthestMeters), each.lap());
  if (!corners.empty()) {
    add(CandidateOrigin::MinSphere, minimumEnclosingSphere(corners), each.lap());
    add(CandidateOrigin::Aabb,
        snapBoxToWalls(axisAlignedBoxFit(corners), view.wallPlanes, snapMeters), each.lap());
    const BoxShape obb = uprightObb ? uprightBoxFit(corners) : orientedBoxFit(corners);
    add(CandidateOrigin::Obb, snapBoxToWalls(obb, view.wallPlanes, snapMeters), each.lap());
  }
  if (const std::optional<BoxShape> room = roomBox(capture, view.axisWallsMeters, corners))
    add(CandidateOrigin::RoomBox, holdingShadingPoints(*room, fitSamples), each.lap());
  f.fitMs = fitTime.ms();
  if (f.hull) add(CandidateOrigin::Hull, *f.hull, f.hullMs);
  const bool anyBox = std::any_of(f.candidates.begin(), f.candidates.end(), [](const auto& c) {
    return std::holds_alternative<BoxShape>(c.shape) && holdsVolume(c.shape);
  });
  if (!anyBox) {
    f.findings.push_back(
        "no box holds a volume: proxies.json has no box preset for this probe (Unity, HDRP, "
        "Unreal's box, Godot, Bevy, EEVEE); in the engine, leave its box projection off");
  }
  return f;
}

}  // namespace probeproxy
