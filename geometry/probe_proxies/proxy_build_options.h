#pragma once
// What the proxy build may do and what it must reach: the tolerance the kept proxy meets, the
// plane budget, the depth cube the candidates are fitted to and the reflection samples they
// are measured on.

#include "geometry/evaluation/reflection_samples.h"

namespace probeproxy {

struct ProxyBuildOptions {
  double toleranceDeg = 0.25;  // keep the fewest planes whose mirror_floor p95 is under this
  int maxPlanes = 64;          // never keep more planes than this
  double maxMissRate = 0.001;  // a kept proxy may miss at most this share of visible samples
  int depthFaceSize = 128;     // depth cube the candidates are fitted to
  bool regenerate = false;     // build a proxy even where the scene file has an authored one
  bool uprightObb = false;     // the obb candidate stands upright, no optimizer (layout)
  // Keep only a shape layout chooses among (layoutChoosesAmong): one a scene file can author
  // (layout writes its kept proxies into one), and not cheap_k. Allowed in layout's coarse
  // candidates and its fits to a range's floor too, cheap_k moved ranges and the validation
  // maps got worse (bleach 296 -> 306 probes, p95 38.3 -> 40.6 deg, floor over 5 deg 23.9% ->
  // 24.2%); layout_proxy.h lets it serve a probe's floor in the blend alone.
  bool layoutShapesOnly = false;
  // The simplification starts from planes grown to hold the fit samples' floor
  // (hold_shading_points.h): layout's final fits (layout_proxy.h). Not `build`'s default: on
  // the corpus's spawn-point probes it took p95 down (warfare 55.3 -> 40.9 deg, basement 67.1
  // -> 49.8) but the floor over 5 deg up on eight maps of ten (downer 9.1% -> 10.2%); nor layout's
  // coarse candidates: their 12 m and whole-view fits then claimed floor the final proxies did
  // not serve, and the selection took fewer, larger ranges (downer 139 -> 131 probes, p95
  // 29.3 -> 32.9 deg).
  bool simplifyHoldingFloor = false;
  ReflectionSampleOptions samples;

  // Throws InputError naming the first option outside its range (core/errors/option_checks.h):
  // tolerance_deg > 0, max_planes in [4, 256], max_miss_rate in [0, 1], face_size in
  // [8, 2048], samples in [64, 1000000].
  void check() const;
};

// The proxy `validate` compares a scene's own with (proxy_error_rule.cpp): `build`'s, generated
// whatever the scene authored, kept by the scene's tolerance. The layout finds the same one
// among its whole box's candidates, so that validate never hints at a proxy the layout did not
// weigh (layout_proxy.cpp, keptAsGenerated).
ProxyBuildOptions generatedForComparison(double toleranceDeg,
                                         const ReflectionSampleOptions& samples);

}  // namespace probeproxy
