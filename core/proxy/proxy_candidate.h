#pragma once
// What `build` produces for a probe: every candidate proxy it tried, with its error, and the
// one it kept. World frame (Z up), metres. Plain data.

#include "core/measures/error_figures.h"
#include "core/proxy/proxy_shape.h"

#include <string>
#include <vector>

namespace probeproxy {

struct ProxyCandidate {
  std::string kind;  // "infinite", "cheap_k", "sphere", "aabb", "obb", "hull", "convex_k",
                     // "authored": how it was made (the method is methodId(shape))
  ProxyShape shape;
  ErrorFigures error;             // on the probe's `mirror_floor` sample set
  ErrorFigures errorAllSurfaces;  // measured for the kept one and each non-convex_k kind;
                                  // samples == 0 where not measured
  double buildMs = 0.0;           // time to make this candidate (not to evaluate it)
};

struct ProbeProxyBuild {
  std::string probe;     // the probe's name
  std::size_t kept = 0;  // index into candidates
  std::vector<ProxyCandidate> candidates;
  double buildMs = 0.0;  // whole probe: sampling, fits, simplification, evaluation
  // Where the time went, ms: depth cube, reflection samples + true hits, hull, simplification,
  // other fits, evaluation.
  double depthMs = 0.0, samplingMs = 0.0, hullMs = 0.0, simplifyMs = 0.0, fitMs = 0.0,
         evaluateMs = 0.0;
  // What kept the build from doing its best, one line each, e.g. that the capture point is
  // outside the level. The build still keeps the best candidate it could make.
  std::vector<std::string> findings;
};

}  // namespace probeproxy
