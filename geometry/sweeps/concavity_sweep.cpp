// Sweep (e) of break_sweeps.h: the L-room's arms grow; the proxies the build pipeline makes
// from what the corner probe sees, and the bounding box an artist would draw, are measured on
// the build's own mirror_floor samples against the true hits (Embree).

#include "core/proxy/proxy_shape.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/builtin/l_room.h"
#include "geometry/sweeps/break_sweeps.h"

#include <algorithm>

namespace probeproxy {

namespace {

// A probe like the suite's L-room probes (scripts/scenes/suite): captured at eye height 1.6 m,
// influence 0.75 m past a w x w square around it (w the room's width). `alongXMeters` moves it
// from the corner room's centre (w / 2, w / 2) into the x arm.
Probe lRoomProbe(double w, double alongXMeters) {
  Probe probe;
  probe.name = alongXMeters > 0 ? "arm" : "corner";
  probe.captureMeters = {w / 2 + alongXMeters, w / 2, 1.6};
  BoxInfluence influence;
  influence.centerMeters = {probe.captureMeters.x, w / 2, 1.5};
  influence.halfExtentsMeters = {w / 2 + 0.75, w / 2 + 0.75, 1.5};
  influence.innerHalfExtentsMeters = {w / 2, w / 2, 1.5};
  probe.influence = influence;
  return probe;
}

SweepPoint pointOf(double arm, const ProxyCandidate& c) {
  return {arm, c.error, 0, std::nullopt, planeCount(c.shape)};
}

const ProxyCandidate& candidateOfKind(const ProbeProxyBuild& build, CandidateOrigin origin) {
  const auto it = std::find_if(build.candidates.begin(), build.candidates.end(),
                               [&](const ProxyCandidate& c) { return c.origin == origin; });
  if (it == build.candidates.end())
    throw std::logic_error("concavity sweep: the build made no such candidate");
  return *it;
}

}  // namespace

Sweep concavitySweep() {
  Sweep sweep{"concavity", "L-room arm length past the 4 m corner room (m)", {}};
  sweep.series = {{"artist_box", {}},
                  {"build_kept", {}},
                  {"infinite", {}},
                  {"corner_artist_box", {}},
                  {"corner_build_kept", {}}};
  ProxyBuildOptions options;
  options.regenerate = true;  // the artist's box is measured beside the build, never kept
  for (double armMeters : {0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0}) {
    const LRoomSize size{4.0, armMeters, 3.0};
    const LevelRayCaster level(lRoom(size));
    const double far = size.widthMeters + armMeters;
    const BoxShape artistBox{{far / 2, far / 2, 1.5}, {far / 2, far / 2, 1.5}};
    // The arm probe stays 2 m from the x arm's end wall; with no arm it is the corner probe.
    const ProbeProxyBuild inArm =
        buildProbeProxy(level, lRoomProbe(4.0, armMeters), artistBox, options);
    sweep.series[0].points.push_back(
        pointOf(armMeters, candidateOfKind(inArm, CandidateOrigin::Authored)));
    sweep.series[1].points.push_back(pointOf(armMeters, inArm.candidates[inArm.kept]));
    sweep.series[2].points.push_back(
        pointOf(armMeters, candidateOfKind(inArm, CandidateOrigin::Infinite)));
    const ProbeProxyBuild corner = buildProbeProxy(level, lRoomProbe(4.0, 0), artistBox, options);
    sweep.series[3].points.push_back(
        pointOf(armMeters, candidateOfKind(corner, CandidateOrigin::Authored)));
    sweep.series[4].points.push_back(pointOf(armMeters, corner.candidates[corner.kept]));
  }
  return sweep;
}

}  // namespace probeproxy
