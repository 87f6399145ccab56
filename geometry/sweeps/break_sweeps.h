#pragma once
// Where each correction method breaks: sweeps of one parameter on analytic box rooms, each
// measuring the float kernels (prepareProxy + lookupBatch, what a shader runs) against the
// exact answer in double precision. The unit tests assert graceful behaviour on them (no NaN
// or inf, failures flagged as misses, error growing where theory says); `break_sweeps` (tests/
// bench) prints them as JSON for scripts/bench_charts.py. Deterministic (fixed seeds).
//
// The room: an axis-aligned box, centre (0, 0, 1.5) m, half-extents (5, 4, 1.5) m.

#include "core/measures/error_figures.h"

#include <optional>
#include <string>
#include <vector>

namespace probeproxy {

struct SweepPoint {
  double parameter = 0.0;     // in the sweep's unit
  ErrorFigures error;         // angular error of the lookup against the exact one, degrees
  std::size_t nonFinite = 0;  // lookups that were neither flagged misses nor finite (must be 0)
  std::optional<double> imageMeanAbsError;  // resolution sweep: bilinear fetch against the exact
                                            // radiance (linear units, radiance in [0, 1])
  std::optional<int> planes;  // concavity sweep: planes of the proxy measured at this point
};

struct SweepSeries {
  std::string method;  // docs/methods_and_measures.md's id, or "reference_double", "mixing_plane"
  std::vector<SweepPoint> points;
};

struct Sweep {
  std::string name;       // "distance", "roughness", "capture", "origin", "concavity",
                          // "resolution"
  std::string parameter;  // what is swept, with its unit
  std::vector<SweepSeries> series;
};

// (a) shading points at a distance (m) from the capture point, random directions.
Sweep distanceSweep();
// (b) GGX roughness of a floor seen from a camera at eye height: the mixing step (one
// corrected cube from the reflected camera, fetched along the perturbed reflection) against
// per-pixel correction of the same rays; exact proxy, so every error is the method's.
Sweep roughnessSweep();
// (c) the capture point moving along x to and past the proxy's wall at x = 1 m (the room goes
// on to x = 5 m); shading points on the floor within 1.5 m of it.
Sweep captureSweep();
// (d) the whole level moved 1 m to 1e6 m from the world origin along (1, 1, 1).
Sweep originSweep();
// (e) how concave the room is: the L-room (geometry/builtin/l_room.h, 4 m wide, 3 m high) with
// arms 0 m to 12 m long, its corner probe as the suite's (capture (2, 2, 1.6), influence 2.75 m
// around it). Series on the build's mirror_floor samples (true hits by Embree): `artist_box`,
// the room's bounding box as an artist would draw it; `build_kept`, the proxy buildProbeProxy
// keeps; `hull`, the convex hull of what the probe sees; `infinite`. Declared here, built in
// concavity_sweep.cpp with the proxy pipeline.
Sweep concavitySweep();
// (f) cubemap face size: direction quantisation (nearest texel centre) and bilinear image error.
Sweep resolutionSweep();

std::vector<Sweep> allSweeps();

// The first parameter at which the series' p95 exceeds limitDeg (none if it never does).
std::optional<double> firstP95Above(const SweepSeries& series, double limitDeg);

// {"sweeps": [{"name", "parameter", "series": [{"method", "points": [{"parameter",
// "median_deg", "p95_deg", "miss_rate", "non_finite", "image_mae", "planes"}]}]}]}
std::string sweepsJson(const std::vector<Sweep>& sweeps);

}  // namespace probeproxy
