// On a real map: a layout probe's proxy fitted to its inner range alone ended
// just past it, and the floor its band shares with a neighbour fell outside the proxy.

#include "core/proxy/proxy_candidate.h"
#include "geometry/evaluation/evaluate_shape.h"
#include "geometry/evaluation/reflection_samples.h"
#include "geometry/layout/layout_proxy.h"
#include "geometry/level/load_level.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/probe_proxies/room_box.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/scene/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace probeproxy {
namespace {

LevelMesh corpusLevel(const std::string& map) {
  return loadLevel(
      readSceneFile(std::string(PROBEPROXY_CORPUS_SCENES) + "/" + map + "/" + map + ".scene.json"));
}

// A probe of a corpus layout, as its layout.scene.json gives it.
Probe layoutProbe(const std::string& name, glm::dvec3 capture, glm::dvec3 center,
                  glm::dvec3 halfExtents, glm::dvec3 innerHalfExtents) {
  Probe probe;
  probe.name = name;
  probe.captureMeters = capture;
  BoxInfluence box;
  box.centerMeters = center;
  box.halfExtentsMeters = halfExtents;
  box.innerHalfExtentsMeters = innerHalfExtents;
  probe.influence = box;
  return probe;
}

TEST(BuildLayoutProxy, OnDownerTheKeptProxyHoldsTheFloorItsBandShares) {
  // probe_013 of a downer layout whose gaps had been moved (an experiment): fitted to
  // its inner range alone, its proxy left out floor just past it, 141 degrees of mean error there.
  const LevelRayCaster level(corpusLevel("downer"));
  const glm::dvec3 innerHalf(2.5, 4.75, 1.906249985);
  const Probe probe = layoutProbe("probe_013", {9.25, 19.25, -5.21}, {8.5, 16.75, -5.406249955},
                                  {4.0, 6.25, 2.156249985}, innerHalf);
  ProxyBuildOptions o;

  Probe inner = probe, majority = probe;
  std::get<BoxInfluence>(inner.influence).halfExtentsMeters = innerHalf;
  majority.influence = majorityRange(probe.influence);
  const ProbeProxyBuild tight = buildProbeProxy(level, inner, std::nullopt, o);
  const ProbeProxyBuild kept = buildLayoutProxy(level, probe, o, 0.0, 5.0);
  ReflectionSampleOptions so = o.samples;
  so.seed += 7;
  so.connectedFloorOnly = false;
  const auto shared = buildReflectionSamples(level, majority, SampleSet::MirrorFloor, so);
  const ErrorFigures k =
      evaluateShape(kept.candidates[kept.kept].shape, probe.captureMeters, shared);
  const ErrorFigures t =
      evaluateShape(tight.candidates[tight.kept].shape, probe.captureMeters, shared);
  // The inner fit misses one reflection in twenty off the floor within half a gap of the range.
  EXPECT_GT(t.missRate, 0.02);
  EXPECT_LE(k.missRate, o.maxMissRate);
  EXPECT_LT(k.meanCostDeg, 0.5 * t.meanCostDeg);
  EXPECT_LT(k.p95WithMissesDeg, 0.5 * t.p95WithMissesDeg);
  // Both are chosen on the inner range's floor, where the kept one stays near the inner fit.
  EXPECT_LE(kept.candidates[kept.kept].error.meanCostDeg,
            tight.candidates[tight.kept].error.meanCostDeg + 1.0);
}

TEST(BuildProbeProxy, OnWarfareTheRoomBoxHoldsTheFloorPastItsWalls) {
  // probe_027's inner range in an earlier warfare layout: the walls its axis rays find stand
  // short of some of its floor, and the room box that modelled the rest at 1.6 degrees median
  // missed one reflection in fifty; a sphere at 10.5 degrees median was kept instead.
  const LevelRayCaster level(corpusLevel("warfare"));
  const glm::dvec3 innerHalf(3.5, 2.5, 1.5625);  // the inner range alone
  const Probe probe =
      layoutProbe("probe_027", {-8.75, 16.75, 6.6}, {-8.5, 19.0, 6.0625}, innerHalf, innerHalf);
  const ProxyBuildOptions o;
  const ProbeProxyBuild build = buildProbeProxy(level, probe, std::nullopt, o);

  const std::optional<BoxShape> walls =
      roomBox(probe.captureMeters, axisWallDistances(level, probe.captureMeters), {});
  ASSERT_TRUE(walls.has_value());
  ReflectionSampleOptions so = o.samples;
  so.seed += 7;
  const auto floor = buildReflectionSamples(level, probe, SampleSet::MirrorFloor, so);
  EXPECT_GT(evaluateShape(*walls, probe.captureMeters, floor).missRate, 0.01);
  const auto room =
      std::find_if(build.candidates.begin(), build.candidates.end(),
                   [](const ProxyCandidate& c) { return c.origin == CandidateOrigin::RoomBox; });
  ASSERT_NE(room, build.candidates.end());
  EXPECT_LE(room->error.missRate, o.maxMissRate);
  EXPECT_LT(room->error.medianDeg, 2.5);
  EXPECT_LT(build.candidates[build.kept].error.medianDeg, 2.5);
}

}  // namespace
}  // namespace probeproxy
