// The proxy build wire (geometry/layout/proxy_build_wire.h): a probe's task and its whole build
// read back exactly as packed, wherever they ran, and bytes it did not write are refused by name.

#include "geometry/layout/proxy_build_wire.h"

#include "geometry/builtin/box_room.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "tests/unit/room_probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

namespace probeproxy {
namespace {

ProbeProxyBuild boxRoomBuild() {
  const glm::dvec3 lo(-4, -2, 0), hi(6, 3, 3);
  const LevelRayCaster level(boxRoom(glm::vec3(lo), glm::vec3(hi)));
  ProxyBuildOptions o;
  o.depthFaceSize = 48;
  o.samples.targetSamples = 1024;
  ProbeProxyBuild build = buildProbeProxy(level, probeAt({1, 0.5, 1.6}, lo, hi), std::nullopt, o);
  build.findings = {"the capture point is 0.1 m from a wall", ""};
  return build;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ProxyBuildWire, ABuildReadsBackWithEveryCandidateAndFigure) {
  const ProbeProxyBuild sent = boxRoomBuild();
  // The build holds every kind of shape the wire carries.
  std::set<std::size_t> kinds;
  for (const ProxyCandidate& c : sent.candidates) kinds.insert(c.shape.index());
  ASSERT_EQ(kinds.size(), std::variant_size_v<ProxyShape>);

  const std::string wire = packProxyBuild(sent);
  const ProbeProxyBuild got = unpackProxyBuild(wire);
  EXPECT_EQ(got.probe, sent.probe);
  EXPECT_EQ(got.kept, sent.kept);
  EXPECT_EQ(got.findings, sent.findings);
  EXPECT_TRUE(sameBits(got.buildMs, sent.buildMs));
  EXPECT_TRUE(sameBits(got.evaluateMs, sent.evaluateMs));
  ASSERT_EQ(got.candidates.size(), sent.candidates.size());
  for (std::size_t c = 0; c < sent.candidates.size(); ++c) {
    const ProxyCandidate &a = sent.candidates[c], &b = got.candidates[c];
    EXPECT_EQ(candidateName(b), candidateName(a));
    EXPECT_EQ(b.origin, a.origin);
    EXPECT_EQ(b.shape.index(), a.shape.index());
    EXPECT_TRUE(sameBits(b.error.p95Deg, a.error.p95Deg));  // NaN where not measured, too
    EXPECT_TRUE(sameBits(b.errorAllSurfaces.medianDeg, a.errorAllSurfaces.medianDeg));
    EXPECT_EQ(b.error.samples, a.error.samples);
    if (const auto* convex = std::get_if<ConvexProxy>(&a.shape)) {
      const auto& back = std::get<ConvexProxy>(b.shape);
      ASSERT_EQ(back.planes.size(), convex->planes.size());
      EXPECT_EQ(back.triangles, convex->triangles);
      EXPECT_EQ(back.verticesMeters, convex->verticesMeters);
    }
  }
  EXPECT_EQ(packProxyBuild(got), wire);  // byte for byte
}

TEST(ProxyBuildWire, ATaskReadsBackAsTheProbeTheBuildReads) {
  ProxyBuildTask box;
  box.probe = probeAt({1.25, -0.5, 1.6}, {-4, -2, 0}, {6, 3, 3});
  box.candidateFitMeters = 12.5;
  box.probe.name = "probe_017";
  std::get<BoxInfluence>(box.probe.influence).worldFromBox = glm::dquat(0.8, 0, 0, 0.6);
  ProxyBuildTask sphere = box;
  sphere.candidateFitMeters = 0.0;
  sphere.probe.influence = SphereInfluence{{3, 2, 1.5}, 7.25, 6.0};
  box.blendVolumes = {sphere.probe.influence, box.probe.influence};
  box.blendIndex = 1;
  for (const ProxyBuildTask& sent : {box, sphere}) {
    const std::string wire = packProxyBuildTask(sent);
    const ProxyBuildTask got = unpackProxyBuildTask(wire);
    EXPECT_EQ(got.probe.name, sent.probe.name);
    EXPECT_EQ(got.probe.captureMeters, sent.probe.captureMeters);
    EXPECT_EQ(got.candidateFitMeters, sent.candidateFitMeters);
    ASSERT_EQ(got.probe.influence.index(), sent.probe.influence.index());
    ASSERT_EQ(got.blendVolumes.size(), sent.blendVolumes.size());
    for (std::size_t i = 0; i < got.blendVolumes.size(); ++i)
      EXPECT_EQ(got.blendVolumes[i].index(), sent.blendVolumes[i].index());
    EXPECT_EQ(got.blendIndex, sent.blendIndex);
    EXPECT_EQ(packProxyBuildTask(got), wire);
  }
  const ProxyBuildTask got = unpackProxyBuildTask(packProxyBuildTask(box));
  EXPECT_EQ(std::get<BoxInfluence>(got.probe.influence).worldFromBox, glm::dquat(0.8, 0, 0, 0.6));
}

template <class Read>
void expectRefused(Read read, const std::string& bytes, const std::string& message) {
  try {
    read(bytes);
    FAIL() << "accepted: " << message;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(ProxyBuildWire, RefusesBytesItDidNotWrite) {
  const auto readBuild = [](const std::string& b) { unpackProxyBuild(b); };
  const auto readTask = [](const std::string& b) { unpackProxyBuildTask(b); };
  ProbeProxyBuild small;
  small.probe = "p";
  small.candidates.resize(1);
  const std::string wire = packProxyBuild(small);
  expectRefused(readBuild, "PPBT", "proxy build wire: not a proxy build (no PPBB header)");
  expectRefused(readTask, wire, "proxy build wire: not a proxy build task (no PPBT header)");
  ProxyBuildTask lost;
  lost.blendVolumes = {SphereInfluence{{0, 0, 0}, 2.0, 1.0}};
  lost.blendIndex = 1;
  expectRefused(readTask, packProxyBuildTask(lost),
                "proxy build wire: the probe's volume is 1 of 1");
  std::string future = wire;
  future[4] = 3;
  expectRefused(readBuild, future, "proxy build wire: version 3, this program reads 2");
  expectRefused(readBuild, wire.substr(0, 20),
                "proxy build wire: 20 bytes end at 17, 8 more expected");
  expectRefused(readBuild, wire + "x", "proxy build wire: 1 bytes after the build");
  ProbeProxyBuild keptPast = small;
  keptPast.kept = 1;
  expectRefused(readBuild, packProxyBuild(keptPast), "proxy build wire: kept candidate 1 of 1");
  // A count the bytes left cannot hold is refused before anything is made for it.
  std::string many = wire;
  many[4 + 4 + 8 + 1 + 8] = '\x7f';      // the candidate count's low byte
  many[4 + 4 + 8 + 1 + 8 + 7] = '\x7f';  // and its high byte
  EXPECT_THROW(unpackProxyBuild(many), std::runtime_error);
  ProbeProxyBuild badMesh = small;
  ConvexProxy convex;
  convex.verticesMeters = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  convex.triangles = {{0, 1, 3}};
  badMesh.candidates[0].shape = convex;
  expectRefused(readBuild, packProxyBuild(badMesh),
                "proxy build wire: a proxy triangle names corner 3 of 3");
}

}  // namespace
}  // namespace probeproxy
