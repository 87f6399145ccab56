#pragma once
// What one candidate probe would give the floor: its proxy, built as `build` builds one for a
// sphere of influence of `fitMeters` (fitted on the floor connected to the capture point) but
// coarse, and the floor samples it serves within the tolerance among those it sees
// (capture_sight.h; evaluate_shape.h's angle, a miss is 180 degrees). A small fit region models
// one room exactly, a large one all the capture point sees roughly; the cover chooses between
// them by the floor each serves.

#include "core/proxy/proxy_shape.h"
#include "core/scene/probe.h"
#include "geometry/layout/index_set.h"
#include "geometry/layout/layout_options.h"
#include "geometry/probe_proxies/fit_candidates.h"
#include "geometry/probe_proxies/probe_view.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/floor_samples.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

// The fit regions every capture point is tried with: a room, a few rooms, and all the floor it
// sees (the farthest seen floor point's distance); none past the layout's reach.
inline constexpr double kRoomFitMeters = 4.0, kRoomsFitMeters = 12.0;
std::vector<double> fitRadiiFor(double farthestSeenMeters, double reachMeters);

struct CandidateService {
  std::size_t capture = 0;  // index of its capture point (and of that point's sight)
  glm::dvec3 captureMeters{0.0};
  double fitMeters = 0.0;  // the radius of the floor its proxy was fitted to
  ProxyShape proxy;
  IndexSet served;       // seen samples with error <= tolerance
  double buildMs = 0.0;  // proxy and evaluation
};

// What a capture point sees, made once for all its fit regions: the depth cube at the
// candidates' face size and the hull of it.
struct CaptureView {
  ProbeView view;
  ViewHull hull;
};
CaptureView seeFromCapture(const LevelRayCaster& level, glm::dvec3 captureMeters,
                           const LayoutOptions& options);

// `seen`: the samples the capture point sees (CaptureSight::seen).
CandidateService serveFloor(const LevelRayCaster& level, const CaptureView& view, double fitMeters,
                            std::span<const FloorSample> samples, const IndexSet& seen,
                            const LayoutOptions& options);

// A proxy's error on each of `seen` (a miss is kMissErrorDeg), ascending by sample.
std::vector<float> errorsOnSeen(const ProxyShape& proxy, glm::dvec3 captureMeters,
                                std::span<const FloorSample> samples, const IndexSet& seen);

// The sphere a candidate's proxy is fitted to: the floor connected to the capture point in it.
Probe candidateFitProbe(glm::dvec3 captureMeters, double fitMeters);

}  // namespace probeproxy
