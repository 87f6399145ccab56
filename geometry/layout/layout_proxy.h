#pragma once
// Each chosen probe's proxy (docs/layout.md, step 7). The runtime shades a probe's inner range
// with it alone, and its band with it and a neighbour: a proxy fitted to the inner range alone
// can end just past it (a plane where the fit's floor stopped, not a wall), and every
// reflection off the band's floor beyond that plane is a miss, 180 degrees at the probe's
// weight there: on downer, stormkeep and bloodprison such misses were about half of all the
// error the survey found.

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"
#include "geometry/probe_proxies/proxy_build_options.h"
#include "geometry/raycast/level_ray_caster.h"

namespace probeproxy {

// The influence down to where its probe weighs at least as much as a neighbour whose inner
// range stands a gap away (Lagarde's (1 - a) / a is even at half the gap): the inner range
// widened by a third of the band on every side, the band being kOuterBandOverGap gaps deep.
InfluenceVolume majorityRange(const InfluenceVolume& influence);

// Two builds of the probe's proxy, both kept by `build`'s rule on the floor of its inner range:
// one fitted to the reflections of the inner range, one to those of its majority range. The one
// whose mean cost (each miss at 180 degrees) over the majority range's floor is lower is kept;
// a tie keeps the inner fit. The probe's influence is its whole box; the build returned reports
// on its inner range, as `build` on the layout's scene does.
ProbeProxyBuild buildLayoutProxy(const LevelRayCaster& level, const Probe& probe,
                                 const ProxyBuildOptions& options);

}  // namespace probeproxy
