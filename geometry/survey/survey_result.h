#pragma once
// What `survey` found: the DESIGN.md figures, and the floor and per-cell errors the error map is
// drawn from. Plain data. Shares are of the walkable floor's area; errors in degrees are over
// the floor that is covered and whose true hits some weighted probe sees.

#include "geometry/engines/engine.h"
#include "geometry/floor/walkable_floor.h"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace probeproxy {

struct SurveyFigures {
  double walkableSquareMeters = 0.0;
  std::size_t samples = 0;
  std::size_t probes = 0;
  double medianDeg = std::numeric_limits<double>::quiet_NaN();  // area-weighted
  double p95Deg = std::numeric_limits<double>::quiet_NaN();     // area-weighted
  double overToleranceShare = 0.0;  // floor whose error exceeds the tolerance
  double uncoveredShare = 0.0;      // floor no probe reaches (under an engine model, the
                                    // fallback's share of each sample's reflection)
  double occludedShare = 0.0;       // blend weight of probes that cannot see the true hit
  double seconds = 0.0;             // wall time of the whole survey, proxies included
};

// One floor sample: where, what it cost, and how it was split.
struct SurveySampleError {
  double errorDeg = std::numeric_limits<double>::quiet_NaN();  // NaN: uncovered or occluded
  double areaSquareMeters = 0.0;                               // of floor this sample stands for
  double occludedWeight = 0.0;   // blend weight of the probes that cannot see the true hit
  double uncoveredWeight = 0.0;  // the sky / ambient fallback's share: 1 where no probe reaches
  bool uncovered = false;        // no probe reaches the sample at all
  int heaviestProbe = -1;        // the probe that weighs most among those seen (-1: none)
};

// A partly occluded sample, or one the fallback shares, stands for the part of its floor its
// visible probes shade.
inline double shadedArea(const SurveySampleError& e) {
  return e.areaSquareMeters * (1.0 - e.occludedWeight - e.uncoveredWeight);
}

struct SurveyCellError {  // per floor cell (WalkableFloor::cells, same order)
  double p95Deg = std::numeric_limits<double>::quiet_NaN();  // of its samples; NaN: none visible
  // What the map colours: half the cell's shaded floor is at most this. Floor coloured past
  // the tolerance then adds up to about the share the headline counts over it (a cell's p95
  // coloured downer's map 65% at 5 deg or more where 20% of its floor was).
  double medianDeg = std::numeric_limits<double>::quiet_NaN();
  double uncoveredShare = 0.0;
  double occludedShare = 0.0;
  int samples = 0;
};

// What the worst 5% of the shaded floor is (the floor whose error is at the p95 or over): the
// tail that sets the p95, read by what its reflections reach. Shares are of its area and
// overlap (a near hit may lie inside the proxy too).
struct WorstFloor {
  double thresholdDeg = std::numeric_limits<double>::quiet_NaN();  // the p95
  double squareMeters = 0.0;
  double skyShare = 0.0;  // reflections reaching the sky, right only through an infinite lookup
  // True hits within kNearHitMeters of the floor point (a step, a kerb, the foot of a wall).
  double nearHitShare = 0.0;
  // True hits inside the proxy of the probe that weighs most there: level standing in the room
  // (steps, pillars, props), which no convex proxy of the room holds on its faces.
  double hitInsideProxyShare = 0.0;
  struct ProbeShare {
    int probe = 0;  // scene index
    double share = 0.0;
  };
  std::vector<ProbeShare> probes;  // the probe weighing most there, largest share first
};

inline constexpr double kNearHitMeters = 2.0;

struct SurveyResult {
  std::string scene;  // the scene file's stem (e.g. "corridor"), or "scene" in memory
  SurveyFigures figures;
  WalkableFloor floor;
  std::vector<SurveyCellError> cells;
  WorstFloor worst;
  double toleranceDeg = 0.0;        // what over_tolerance_share was measured against
  Engine engine = Engine::Generic;  // whose renderer the figures are for
};

}  // namespace probeproxy
