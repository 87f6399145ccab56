#pragma once
// What `build` produces for a probe: every candidate proxy it tried, with its error, and the
// one it kept. World frame (Z up), metres. Plain data.

#include "core/measures/error_figures.h"
#include "core/proxy/proxy_shape.h"

#include <string>
#include <vector>

namespace probeproxy {

// How the build made a candidate (the method a shader runs for it is methodOf(shape)).
enum class CandidateOrigin {
  Authored,    // the scene file's proxy, measured beside
  Infinite,    // no proxy
  CheapK,      // k fitted to the samples
  Sphere,      // around the capture point, radius fitted to the samples
  MinSphere,   // smallest enclosing the points seen
  Aabb,        // axis-aligned box around them, faces snapped to the walls
  Obb,         // oriented box around them, faces snapped to the walls
  RoomBox,     // the walls along the axes from the capture point (room_box.h)
  Hull,        // their convex hull
  Simplified,  // a step of the hull's error-driven simplification
};

struct ProxyCandidate {
  CandidateOrigin origin = CandidateOrigin::Infinite;
  ProxyShape shape;
  ErrorFigures error;             // on the probe's `mirror_floor` sample set
  ErrorFigures errorAllSurfaces;  // measured for the kept one and each non-convex_k kind;
                                  // samples == 0 where not measured
  double buildMs = 0.0;           // time to make this candidate (not to evaluate it)
};

// The candidate's stable name, for reports only: "authored", "infinite", "cheap_k", "sphere",
// "min_sphere", "aabb", "obb", "hull", or "convex_<planes>" for a simplification step, named
// by the planes its shape holds.
std::string candidateName(const ProxyCandidate& candidate);

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
