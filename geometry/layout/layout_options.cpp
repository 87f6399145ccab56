#include "geometry/layout/layout_options.h"

#include "core/errors/input_error.h"
#include "core/errors/option_checks.h"

namespace probeproxy {

ProxyBuildOptions LayoutOptions::coarseCandidateProxyOptions() {
  ProxyBuildOptions o;
  o.depthFaceSize = 32;
  o.samples.targetSamples = 256;
  o.samples.camerasAcross = 4;
  o.maxPlanes = 16;
  o.uprightObb = true;
  o.layoutShapesOnly = true;  // as the final build's (layout_proxy.h)
  return o;
}

void LayoutOptions::check() const {
  requireInRange("tolerance_deg", toleranceDeg, 1e-9, 180.0);
  requireInRange("spacing", spacingMeters, 0.25, 100.0);
  requireInRange("max_candidates", maxCandidates, std::size_t{1}, std::size_t{1'000'000});
  if (reachMeters != 0.0) requireInRange("reach", reachMeters, 0.5, 1000.0);
  if (tileMeters != 0.0) requireInRange("tile_size", tileMeters, 1.0, 100'000.0);
  requireInRange("capture_height", captureHeightMeters, 0.05, 10.0);
  // Wider than any room: the bands reach over the level and past the limits of a scene.
  requireInRange("blend_band", blendBandMeters, 0.0, kMaxBlendBandMeters);
  requireInRange("samples_per_cell", samplesPerCell, 1, 64);
  requireInRange<std::size_t>("max_probes", maxProbes, 0, 100'000);
  if (keepAuthored && baseline != LayoutBaseline::None)
    throw InputError("option keep_authored",
                     "adds probes to the scene's own; it does not go with a baseline");
  floor.check();
  coverFloor.check();
  candidateProxy.check();
  finalProxy.check();
}

}  // namespace probeproxy
