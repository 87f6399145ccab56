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
  ReflectionSampleOptions samples;

  // Throws InputError naming the first option outside its range (core/errors/option_checks.h):
  // tolerance_deg > 0, max_planes in [4, 256], max_miss_rate in [0, 1], face_size in
  // [8, 2048], samples in [64, 1000000].
  void check() const;
};

}  // namespace probeproxy
