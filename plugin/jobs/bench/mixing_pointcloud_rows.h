#pragma once
// `probeproxy bench` rows of the methods that are not a per-ray proxy lookup
// (docs/methods_and_measures.md "Methods"): mixing_plane and raster_convex (the mixing step: a
// corrected cubemap per camera and reflection plane, through the probe's kept proxy) and pointcloud
// (Hodgman's "Imperfect Environment Maps", no proxy).
//
// - mixing_plane, raster_convex: ns_per_lookup is CPU ns per texel of the corrected cubemap
//   (correctCubemap over every mip level, for the first mirror view's reflected camera);
//   median_deg, p95_deg, miss_rate: evaluateMixing on the probe's mirror_floor samples that lie
//   on its first reflection plane; psnr_db: the mirror views rebuilt through the cube corrected
//   for each view's camera. Only for probes whose kept proxy is a box or convex (the step
//   rasterizes planes and triangles) and that have a reflection plane.
// - pointcloud: ns_per_lookup is CPU ns per shading point (splat + fetch); psnr_db over every
//   8th floor pixel of each view (a splat costs about a millisecond); no direction, so the
//   angular figures are null. Only for probes with a cubemap and views (the cloud is made of
//   the cubemap's texels).
// instructions_per_lookup and ns_per_lookup_scalar are null (not measured).

#include "core/proxy/proxy_candidate.h"
#include "core/scene/probe.h"
#include "geometry/evaluation/reflection_sample.h"
#include "geometry/raycast/level_ray_caster.h"
#include "plugin/jobs/bench/bench_result.h"
#include "plugin/jobs/bench/image_reference.h"
#include "plugin/jobs/bench/lookup_timing.h"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace probeproxy::jobs {

struct MethodRow {
  BenchResult row;              // ns_per_lookup filled in from `cost` once it is timed
  std::optional<CallJob> cost;  // owns what it needs
};

struct ProbeBenchInputs {
  std::string scene;
  const Probe* probe = nullptr;                   // not owned
  const LevelRayCaster* level = nullptr;          // not owned
  const ProxyCandidate* kept = nullptr;           // not owned: the build's kept candidate
  std::span<const ReflectionSample> mirrorFloor;  // not owned: the build's report draw
  std::shared_ptr<const ImageReference> images;   // null without cubemap or views
  int faceSize = 128;                             // lookup cubes without a cubemap
};

std::vector<MethodRow> mixingRows(const ProbeBenchInputs& in);
std::vector<MethodRow> pointCloudRows(const ProbeBenchInputs& in);

}  // namespace probeproxy::jobs
