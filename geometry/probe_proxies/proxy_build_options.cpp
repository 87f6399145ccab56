#include "geometry/probe_proxies/proxy_build_options.h"

#include "core/errors/option_checks.h"

namespace probeproxy {

void ProxyBuildOptions::check() const {
  requirePositive("tolerance_deg", toleranceDeg);
  requireInRange("max_planes", maxPlanes, 4, 256);
  requireInRange("max_miss_rate", maxMissRate, 0.0, 1.0);
  requireInRange("face_size", depthFaceSize, 8, 2048);
  samples.check();
}

ProxyBuildOptions generatedForComparison(double toleranceDeg,
                                         const ReflectionSampleOptions& samples) {
  ProxyBuildOptions build;
  build.toleranceDeg = toleranceDeg;
  build.regenerate = true;
  build.samples = samples;
  return build;
}

}  // namespace probeproxy
