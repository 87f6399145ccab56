#pragma once
// Each chosen probe's proxy (docs/layout.md, step 7). The runtime shades a probe's inner range
// with it alone, and its band with it and a neighbour: a proxy fitted to the inner range alone
// can end just past it (a plane where the fit's floor stopped, not a wall), and every
// reflection off the band's floor beyond that plane is a miss, 180 degrees at the probe's
// weight there: on downer and stormkeep such misses were nearly half of all the error the
// survey found (in earlier layouts).

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"
#include "geometry/probe_proxies/proxy_build_options.h"
#include "geometry/raycast/level_ray_caster.h"

#include <span>
#include <vector>

namespace probeproxy {

// The influence down to where its probe weighs at least as much as a neighbour whose inner
// range stands a gap away (Lagarde's (1 - a) / a is even at half the gap): the inner range
// widened by a third of the band on every side, the band being kOuterBandOverGap gaps deep.
InfluenceVolume majorityRange(const InfluenceVolume& influence);

// The volumes the blend weighs a probe against: at least every volume reaching the probe's,
// the probe's among them, in the scene's order (served_error.h: then the weights are the
// scene's).
struct BlendNeighbourhood {
  std::span<const InfluenceVolume> volumes;  // empty: no served-floor step
  int probeIndex = -1;                       // the probe's own volume in `volumes`
};

// The volumes whose outer ranges' bounds meet volumes[index]'s, in order (every one that can
// reach it), and where volumes[index] lies among them: its BlendNeighbourhood, carried alone.
std::vector<InfluenceVolume> volumesMeeting(std::span<const InfluenceVolume> volumes,
                                            std::size_t index, int& indexAmong);

// The probe's proxy, built as `build` builds one and kept by its rule on the floor of the inner
// range, fitted three times: to the reflections of the inner range, of the majority range, and
// of the floor the selection measured the probe's candidate on (a sphere of
// `candidateFitMeters` round the capture point, candidate_service.h; none when 0: a fill).
// Measured on the majority range's floor: the fit whose kept proxy leaves the least floor over
// `toleranceDeg` (the layout's; a miss is over), to the percent, then the lowest mean cost
// (each miss at 180 degrees), is the start; then of the three builds' candidates (their kept
// ones, and any else of at most 16 planes) whose p95 is no worse than the start's and whose
// mean is no higher, the one with the least floor over the tolerance plus floor over 30
// degrees, then the lowest mean, is kept; the earlier on a tie. With a blend neighbourhood, a
// fourth fit to the whole box follows, built twice (simplified holding the floor as the three
// are, and not, as `validate` generates its proxy), and of all five builds' candidates (the
// same ones, each build's cheap_k, which a scene holds but the choices before may not take:
// proxy_build_options.h, and of the last build the one `validate` keeps, whatever its planes)
// the one serving the probe's blend-weighted floor clearly better
// than that choice (served_error.h, on `validate`'s samples), with the least of it over the
// tolerance, then the lowest p95, replaces it. The probe's influence is its whole box; the build
// returned reports on its inner range, as `build` on the layout's scene does.
ProbeProxyBuild buildLayoutProxy(const LevelRayCaster& level, const Probe& probe,
                                 ProxyBuildOptions options, double candidateFitMeters,
                                 double toleranceDeg, const BlendNeighbourhood& blend = {});

}  // namespace probeproxy
