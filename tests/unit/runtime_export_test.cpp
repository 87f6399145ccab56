// The runtime export (proxies.json + proxies.glb): what is written reads back to the same
// world values, in any scene frame and unit, byte for byte the same every time; the unit
// transforms shaders use; each engine's parameters for boxes with hand-computed answers; the
// glb a DCC tool opens; and every refusal to overwrite what an artist made.

#include "geometry/export/runtime_export.h"
#include "core/errors/input_error.h"
#include "core/scene/file_frame.h"
#include "geometry/export/engine_probes.h"
#include "geometry/export/kept_box.h"
#include "geometry/export/unit_transform.h"
#include "geometry/level/load_level.h"
#include "test_files.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

// Outside namespace probeproxy: the suite is named RuntimeExport, like the struct under test,
// which is spelled probeproxy::RuntimeExport here.
namespace probeproxy::runtime_export_test {
namespace {

namespace fs = std::filesystem;
using Runtime = probeproxy::RuntimeExport;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kHalfSqrt2 = std::sqrt(0.5);

glm::dquat quat(double w, double x, double y, double z) {
  glm::dquat q;
  q.w = w;
  q.x = x;
  q.y = y;
  q.z = z;
  return q;
}

glm::dquat aboutZ(double degrees) {
  return glm::angleAxis(glm::radians(degrees), glm::dvec3(0, 0, 1));
}

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// ------------------------------------------------------------------------------------------
// The room: 6 x 4 x 3 m, x in [-3, 3], y in [-2, 2], z in [0, 3]; capture point off centre.

const glm::dvec3 kCapture(1.0, 0.5, 1.2);
const BoxShape kRoomBox{{0.0, 0.0, 1.5}, {3.0, 2.0, 1.5}, quat(1, 0, 0, 0)};

// The room with its two long top edges chamfered: 8 planes. Triangles are found from the
// planes: each face's corners, sorted counter-clockwise about its normal, as a fan.
ConvexProxy chamferedRoom() {
  ConvexProxy convex;
  const double r = kHalfSqrt2;
  convex.planes = {{{1, 0, 0}, 3.0},     {{-1, 0, 0}, 3.0},    {{0, 1, 0}, 2.0},
                   {{0, -1, 0}, 2.0},    {{0, 0, 1}, 3.0},     {{0, 0, -1}, 0.0},
                   {{0, r, r}, r * 4.5}, {{0, -r, r}, r * 4.5}};  // through (0, +-2, 2.5)
  for (double x : {-3.0, 3.0}) {
    for (const glm::dvec2 yz : {glm::dvec2(-2, 0), glm::dvec2(2, 0), glm::dvec2(-2, 2.5),
                                glm::dvec2(2, 2.5), glm::dvec2(-1.5, 3), glm::dvec2(1.5, 3)}) {
      convex.verticesMeters.emplace_back(x, yz.x, yz.y);
    }
  }
  for (const ProxyPlane& plane : convex.planes) {
    std::vector<unsigned> face;
    glm::dvec3 centroid(0.0);
    for (unsigned i = 0; i < convex.verticesMeters.size(); ++i) {
      if (std::abs(glm::dot(plane.normal, convex.verticesMeters[i]) - plane.offsetMeters) < 1e-9) {
        face.push_back(i);
        centroid += convex.verticesMeters[i];
      }
    }
    centroid /= double(face.size());
    const glm::dvec3 u = glm::normalize(convex.verticesMeters[face[0]] - centroid);
    const glm::dvec3 v = glm::cross(plane.normal, u);
    std::sort(face.begin(), face.end(), [&](unsigned a, unsigned b) {
      const glm::dvec3 da = convex.verticesMeters[a] - centroid,
                       db = convex.verticesMeters[b] - centroid;
      return std::atan2(glm::dot(da, v), glm::dot(da, u)) <
             std::atan2(glm::dot(db, v), glm::dot(db, u));
    });
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      convex.triangles.emplace_back(face[0], face[k], face[k + 1]);
  }
  return convex;
}

ErrorFigures figures(double median, double p95, double max, double miss, std::size_t samples) {
  ErrorFigures e;
  e.medianDeg = median;
  e.p95Deg = p95;
  e.maxDeg = max;
  e.missRate = miss;
  e.occludedRate = 0.125;
  e.samples = samples;
  return e;
}

// Every kind of candidate; the obb is a little better than the aabb, so box-only engines
// other than Unity take the obb.
std::vector<ProxyCandidate> roomCandidates() {
  std::vector<ProxyCandidate> c(6);
  c[0] = {CandidateOrigin::Infinite, InfiniteShape{}, figures(kNaN, kNaN, kNaN, 0.0, 0), {}, 0.0};
  c[1] = {CandidateOrigin::CheapK, CheapKShape{0.4}, figures(6.0, 12.0, 20.0, 0.0, 4096), {}, 0.1};
  c[2] = {CandidateOrigin::Sphere,
          SphereShape{{0.0, 0.0, 1.5}, glm::dvec3(3.0), quat(1, 0, 0, 0)},
          figures(3.0, 8.0, 15.0, 0.0, 4096),
          {},
          0.2};
  c[3] = {CandidateOrigin::Aabb, kRoomBox, figures(0.1, 0.5, 2.0, 0.0, 4096), {}, 0.3};
  c[4] = {CandidateOrigin::Obb,
          BoxShape{{0.0, 0.0, 1.5}, {3.1, 2.1, 1.5}, aboutZ(30.0)},
          figures(0.1, 0.4, 2.5, 0.01, 4096),
          {},
          0.4};
  c[5] = {
      CandidateOrigin::Simplified, chamferedRoom(), figures(0.05, 0.2, 1.0, 0.0, 4096), {}, 0.5};
  return c;
}

const char* const kKeptNames[] = {"keep_infinite", "keep_cheap_k", "keep_sphere",
                                  "keep_aabb",     "keep_obb",     "keep_convex"};

Scene roomScene(const fs::path& folder, UpAxis up, double metersPerUnit) {
  Scene scene;
  scene.file = folder / "room.scene.json";
  scene.fileUp = up;
  scene.metersPerUnit = metersPerUnit;
  scene.level.push_back({folder / "room.glb", "room.glb", UpAxis::Y, false, {}});
  for (int i = 0; i < 6; ++i) {
    Probe probe;
    probe.name = kKeptNames[i];
    probe.captureMeters = kCapture;
    if (i % 2 == 0) {
      probe.influence =
          BoxInfluence{{0.0, 0.0, 1.5}, {3.0, 2.0, 1.5}, aboutZ(10.0), {2.5, 1.5, 1.0}};
    } else {
      probe.influence = SphereInfluence{{0.5, 0.0, 1.5}, 4.0, 3.0};
    }
    scene.probes.push_back(probe);
  }
  return scene;
}

std::vector<ProbeProxyBuild> roomBuilds() {
  std::vector<ProbeProxyBuild> builds;
  for (std::size_t i = 0; i < 6; ++i) {
    ProbeProxyBuild build;
    build.probe = kKeptNames[i];
    build.candidates = roomCandidates();
    build.kept = i;
    builds.push_back(build);
  }
  return builds;
}

// ------------------------------------------------------------------------------------------
// Comparisons: exact where the frame is the world's, relative 1e-12 where units convert.

double tolerance(double a, double relative) { return relative * std::max(1.0, std::abs(a)); }

#define EXPECT_CLOSE(a, b, rel)                        \
  do {                                                 \
    const double a_ = (a), b_ = (b);                   \
    if (std::isnan(a_) || std::isnan(b_)) {            \
      EXPECT_EQ(std::isnan(a_), std::isnan(b_)) << #a; \
    } else {                                           \
      EXPECT_NEAR(a_, b_, tolerance(a_, rel)) << #a;   \
    }                                                  \
  } while (0)

void expectClose(glm::dvec3 a, glm::dvec3 b, double rel) {
  for (int i = 0; i < 3; ++i) EXPECT_CLOSE(a[i], b[i], rel);
}

void expectClose(const glm::dquat& a, const glm::dquat& b, double rel) {
  EXPECT_CLOSE(a.w, b.w, rel);
  EXPECT_CLOSE(a.x, b.x, rel);
  EXPECT_CLOSE(a.y, b.y, rel);
  EXPECT_CLOSE(a.z, b.z, rel);
}

void expectClose(const BoxShape& a, const BoxShape& b, double rel) {
  expectClose(a.centerMeters, b.centerMeters, rel);
  expectClose(a.halfExtentsMeters, b.halfExtentsMeters, rel);
  expectClose(a.worldFromBox, b.worldFromBox, rel);
}

void expectClose(const ErrorFigures& a, const ErrorFigures& b) {
  EXPECT_CLOSE(a.medianDeg, b.medianDeg, 0.0);
  EXPECT_CLOSE(a.p95Deg, b.p95Deg, 0.0);
  EXPECT_CLOSE(a.maxDeg, b.maxDeg, 0.0);
  EXPECT_CLOSE(a.missRate, b.missRate, 0.0);
  EXPECT_CLOSE(a.occludedRate, b.occludedRate, 0.0);
  EXPECT_EQ(a.samples, b.samples);
}

void expectClose(const InfluenceVolume& a, const InfluenceVolume& b, double rel) {
  ASSERT_EQ(a.index(), b.index());
  if (const auto* boxA = std::get_if<BoxInfluence>(&a)) {
    const auto& boxB = std::get<BoxInfluence>(b);
    expectClose(boxA->centerMeters, boxB.centerMeters, rel);
    expectClose(boxA->halfExtentsMeters, boxB.halfExtentsMeters, rel);
    expectClose(boxA->worldFromBox, boxB.worldFromBox, rel);
    expectClose(boxA->innerHalfExtentsMeters, boxB.innerHalfExtentsMeters, rel);
  } else {
    const auto& sA = std::get<SphereInfluence>(a);
    const auto& sB = std::get<SphereInfluence>(b);
    expectClose(sA.centerMeters, sB.centerMeters, rel);
    EXPECT_CLOSE(sA.radiusMeters, sB.radiusMeters, rel);
    EXPECT_CLOSE(sA.innerRadiusMeters, sB.innerRadiusMeters, rel);
  }
}

// Engine values are rounded to 1e-9 of the engine's unit when written.
void expectEnginesClose(const RuntimeEngines& a, const RuntimeEngines& b) {
  constexpr double kEngine = 1e-9;
  ASSERT_EQ(a.unity.has_value(), b.unity.has_value());
  ASSERT_EQ(a.unrealBox.has_value(), b.unrealBox.has_value());
  ASSERT_EQ(a.unrealSphere.has_value(), b.unrealSphere.has_value());
  ASSERT_EQ(a.godot.has_value(), b.godot.has_value());
  ASSERT_EQ(a.godot4.has_value(), b.godot4.has_value());
  if (a.godot4) {
    expectClose(a.godot4->size, b.godot4->size, kEngine);
    EXPECT_CLOSE(a.godot4->blendDistance, b.godot4->blendDistance, kEngine);
  }
  ASSERT_EQ(a.bevy.has_value(), b.bevy.has_value());
  ASSERT_EQ(a.unityHdrp.has_value(), b.unityHdrp.has_value());
  ASSERT_EQ(a.eevee.has_value(), b.eevee.has_value());
  if (a.unityHdrp) {
    EXPECT_EQ(a.unityHdrp->source.candidate, b.unityHdrp->source.candidate);
    expectClose(a.unityHdrp->position, b.unityHdrp->position, kEngine);
    expectClose(a.unityHdrp->rotation, b.unityHdrp->rotation, kEngine);
    EXPECT_EQ(a.unityHdrp->sphere, b.unityHdrp->sphere);
    expectClose(a.unityHdrp->boxSize, b.unityHdrp->boxSize, kEngine);
    EXPECT_CLOSE(a.unityHdrp->sphereRadius, b.unityHdrp->sphereRadius, kEngine);
    expectClose(a.unityHdrp->blendDistancePositive, b.unityHdrp->blendDistancePositive, kEngine);
    expectClose(a.unityHdrp->blendDistanceNegative, b.unityHdrp->blendDistanceNegative, kEngine);
    expectClose(a.unityHdrp->capturePosition, b.unityHdrp->capturePosition, kEngine);
    expectClose(a.unityHdrp->proxyPosition, b.unityHdrp->proxyPosition, kEngine);
    expectClose(a.unityHdrp->proxyRotation, b.unityHdrp->proxyRotation, kEngine);
    expectClose(a.unityHdrp->proxySize, b.unityHdrp->proxySize, kEngine);
  }
  if (a.eevee) {
    EXPECT_EQ(a.eevee->source.candidate, b.eevee->source.candidate);
    expectClose(a.eevee->location, b.eevee->location, kEngine);
    expectClose(a.eevee->rotation, b.eevee->rotation, kEngine);
    expectClose(a.eevee->scale, b.eevee->scale, kEngine);
    EXPECT_EQ(a.eevee->sphere, b.eevee->sphere);
    EXPECT_CLOSE(a.eevee->falloff, b.eevee->falloff, kEngine);
    EXPECT_CLOSE(a.eevee->parallaxDistance, b.eevee->parallaxDistance, kEngine);
  }
  if (a.unity) {
    EXPECT_CLOSE(a.unity->blendDistance, b.unity->blendDistance, kEngine);
    EXPECT_EQ(a.unity->importance, b.unity->importance);
    EXPECT_EQ(a.unity->source.candidate, b.unity->source.candidate);
    expectClose(a.unity->source.error, b.unity->source.error);
    expectClose(a.unity->position, b.unity->position, kEngine);
    expectClose(a.unity->center, b.unity->center, kEngine);
    expectClose(a.unity->size, b.unity->size, kEngine);
  }
  if (a.unrealBox) {
    EXPECT_EQ(a.unrealBox->source.candidate, b.unrealBox->source.candidate);
    expectClose(a.unrealBox->location, b.unrealBox->location, kEngine);
    expectClose(a.unrealBox->rotation, b.unrealBox->rotation, kEngine);
    expectClose(a.unrealBox->scale3D, b.unrealBox->scale3D, kEngine);
    expectClose(a.unrealBox->captureOffset, b.unrealBox->captureOffset, kEngine);
    EXPECT_CLOSE(a.unrealBox->boxTransitionDistance, b.unrealBox->boxTransitionDistance, kEngine);
    EXPECT_EQ(a.unrealBox->source.keptProxy, b.unrealBox->source.keptProxy);
  }
  if (a.unrealSphere) {
    expectClose(a.unrealSphere->location, b.unrealSphere->location, kEngine);
    EXPECT_CLOSE(a.unrealSphere->influenceRadius, b.unrealSphere->influenceRadius, kEngine);
    expectClose(a.unrealSphere->captureOffset, b.unrealSphere->captureOffset, kEngine);
  }
  if (a.godot) {
    expectClose(a.godot->origin, b.godot->origin, kEngine);
    expectClose(a.godot->rotation, b.godot->rotation, kEngine);
    expectClose(a.godot->size, b.godot->size, kEngine);
    expectClose(a.godot->originOffset, b.godot->originOffset, kEngine);
    EXPECT_CLOSE(a.godot->blendDistance, b.godot->blendDistance, kEngine);
    EXPECT_EQ(a.godot->source.keptProxy, b.godot->source.keptProxy);
    EXPECT_EQ(a.godot->exact, b.godot->exact);
  }
  if (a.bevy) {
    expectClose(a.bevy->translation, b.bevy->translation, kEngine);
    expectClose(a.bevy->rotation, b.bevy->rotation, kEngine);
    expectClose(a.bevy->scale, b.bevy->scale, kEngine);
    expectClose(a.bevy->falloff, b.bevy->falloff, kEngine);
    EXPECT_EQ(a.bevy->captureAtCentre, b.bevy->captureAtCentre);
    EXPECT_EQ(a.bevy->exact, b.bevy->exact);
  }
}

void expectSameRuntime(const Runtime& read, const Runtime& made, double rel) {
  EXPECT_EQ(read.fileUp, made.fileUp);
  EXPECT_EQ(read.metersPerUnit, made.metersPerUnit);
  ASSERT_EQ(read.probes.size(), made.probes.size());
  for (std::size_t i = 0; i < made.probes.size(); ++i) {
    SCOPED_TRACE(made.probes[i].name);
    const RuntimeProbe& r = read.probes[i];
    const RuntimeProbe& m = made.probes[i];
    EXPECT_EQ(r.name, m.name);
    expectClose(r.captureMeters, m.captureMeters, rel);
    EXPECT_EQ(r.method, m.method);
    EXPECT_EQ(r.candidate, m.candidate);
    ASSERT_EQ(r.kPerMeter.has_value(), m.kPerMeter.has_value());
    if (m.kPerMeter) EXPECT_CLOSE(*r.kPerMeter, *m.kPerMeter, rel);
    ASSERT_EQ(r.box.has_value(), m.box.has_value());
    if (m.box) expectClose(*r.box, *m.box, rel);
    ASSERT_EQ(r.sphere.has_value(), m.sphere.has_value());
    if (m.sphere) {
      expectClose(r.sphere->centerMeters, m.sphere->centerMeters, rel);
      expectClose(r.sphere->radiiMeters, m.sphere->radiiMeters, rel);
      expectClose(r.sphere->worldFromSphere, m.sphere->worldFromSphere, rel);
    }
    ASSERT_EQ(r.worldToUnit.has_value(), m.worldToUnit.has_value());
    if (m.worldToUnit) {
      for (int c = 0; c < 4; ++c) {
        for (int row = 0; row < 4; ++row)
          EXPECT_CLOSE((*r.worldToUnit)[c][row], (*m.worldToUnit)[c][row], rel);
      }
    }
    ASSERT_EQ(r.convex.planes.size(), m.convex.planes.size());
    for (std::size_t p = 0; p < m.convex.planes.size(); ++p) {
      expectClose(r.convex.planes[p].normal, m.convex.planes[p].normal, rel);
      EXPECT_CLOSE(r.convex.planes[p].offsetMeters, m.convex.planes[p].offsetMeters, rel);
    }
    ASSERT_EQ(r.convex.verticesMeters.size(), m.convex.verticesMeters.size());
    for (std::size_t v = 0; v < m.convex.verticesMeters.size(); ++v) {
      expectClose(r.convex.verticesMeters[v], m.convex.verticesMeters[v], rel);
    }
    EXPECT_EQ(r.convex.triangles, m.convex.triangles);
    EXPECT_EQ(r.meshIsDisplayOnly, m.meshIsDisplayOnly);
    EXPECT_EQ(r.planesCount, m.planesCount);
    expectClose(r.influence, m.influence, rel);
    EXPECT_EQ(r.enlighten.epsilon, m.enlighten.epsilon);
    expectClose(r.enlighten.box, m.enlighten.box, rel);
    expectClose(r.error, m.error);
    expectEnginesClose(r.engines, m.engines);
  }
}

class RuntimeExport : public testing::TempFolderTest {
 protected:
  fs::path out() const { return folder_ / "export"; }
};

// ------------------------------------------------------------------------------------------

TEST_F(RuntimeExport, EveryKindReadsBackExactly) {
  const Scene scene = roomScene(folder_, UpAxis::Z, 1.0);
  const Runtime made = makeRuntimeExport(scene, roomBuilds());
  writeRuntimeExport(scene, roomBuilds(), out());
  const Runtime read = readRuntimeExport(out() / "proxies.json");
  expectSameRuntime(read, made, 0.0);  // Z up, metres: bit for bit

  ASSERT_EQ(made.probes.size(), 6u);
  const char* kinds[] = {"infinite", "cheap_k", "sphere", "aabb", "obb", "convex"};
  const int planes[] = {0, 0, 0, 6, 6, 8};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(methodName(read.probes[i].method), kinds[i]);
    EXPECT_EQ(read.probes[i].planesCount, planes[i]);
  }
  EXPECT_TRUE(read.probes[0].convex.verticesMeters.empty());
  EXPECT_DOUBLE_EQ(*read.probes[1].kPerMeter, 0.4);
  EXPECT_TRUE(read.probes[2].meshIsDisplayOnly);
  EXPECT_TRUE(read.probes[2].convex.planes.empty());
  EXPECT_EQ(read.probes[2].convex.verticesMeters.size(), 162u);
  EXPECT_EQ(read.probes[3].convex.planes.size(), 6u);
  EXPECT_EQ(read.probes[3].convex.verticesMeters.size(), 8u);
  EXPECT_EQ(read.probes[5].convex.planes.size(), 8u);
  EXPECT_EQ(read.probes[5].convex.verticesMeters.size(), 12u);
  EXPECT_TRUE(std::isnan(read.probes[0].error.p95Deg));  // written as null
  EXPECT_EQ(read.probes[4].error.p95Deg, 0.4);
  EXPECT_EQ(read.probes[4].enlighten.epsilon, 1e-6);
}

TEST_F(RuntimeExport, UnityImportanceReadsBackAndDefaultsToUnitysOne) {
  Runtime made = makeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds());
  ASSERT_TRUE(made.probes[3].engines.unity);
  EXPECT_EQ(made.probes[3].engines.unity->importance, 1);  // Unity's default
  made.probes[3].engines.unity->importance = 7;
  std::string json = runtimeExportJson(made);
  expectSameRuntime(parseRuntimeExport(json, "proxies.json"), made, 0.0);
  // Written before importance was: Unity's default.
  const std::string written = R"("importance": 7)";
  const std::size_t at = json.find(written);
  ASSERT_NE(at, std::string::npos);
  json.replace(at, written.size(), R"("written_before": 0)");
  EXPECT_EQ(parseRuntimeExport(json, "proxies.json").probes[3].engines.unity->importance, 1);
}

TEST_F(RuntimeExport, YUpCentimetreSceneRoundTripsToTheSameWorldValues) {
  const Scene metres = roomScene(folder_, UpAxis::Z, 1.0);
  const Scene centimetres = roomScene(folder_, UpAxis::Y, 0.01);
  writeRuntimeExport(centimetres, roomBuilds(), out());
  const Runtime read = readRuntimeExport(out() / "proxies.json");
  EXPECT_EQ(read.fileUp, UpAxis::Y);
  EXPECT_EQ(read.metersPerUnit, 0.01);

  Runtime expected = makeRuntimeExport(metres, roomBuilds());
  expected.fileUp = UpAxis::Y;
  expected.metersPerUnit = 0.01;
  expectSameRuntime(read, expected, 1e-12);

  // Written in the artist's frame and unit: world (1, 0.5, 1.2) m is Y-up (1, 1.2, -0.5), in cm.
  const std::string json = readBytes(out() / "proxies.json");
  EXPECT_NE(json.find(R"("up": "Y")"), std::string::npos);
  EXPECT_NE(json.find(R"("meters_per_unit": 0.01)"), std::string::npos);
  EXPECT_NE(json.find(R"("capture": [100.0, 120.0, -50.0])"), std::string::npos);
  // The room's half-extents (3, 2, 1.5) m along its own axes: Y-up (3, 1.5, 2) m, in cm.
  EXPECT_NE(json.find(R"("half_extents": [300.0, 150.0, 200.0])"), std::string::npos);
  // k per centimetre: 0.4 per metre is 0.004 per centimetre.
  EXPECT_NE(json.find(R"("k": 0.004)"), std::string::npos);
}

TEST_F(RuntimeExport, SameInputGivesTheSameBytes) {
  const Scene scene = roomScene(folder_, UpAxis::Y, 0.01);
  writeRuntimeExport(scene, roomBuilds(), folder_ / "a");
  writeRuntimeExport(scene, roomBuilds(), folder_ / "b");
  const std::string jsonA = readBytes(folder_ / "a" / "proxies.json");
  const std::string glbA = readBytes(folder_ / "a" / "proxies.glb");
  EXPECT_EQ(jsonA, readBytes(folder_ / "b" / "proxies.json"));
  EXPECT_EQ(glbA, readBytes(folder_ / "b" / "proxies.glb"));
  writeRuntimeExport(scene, roomBuilds(), folder_ / "a");  // over our own export
  EXPECT_EQ(jsonA, readBytes(folder_ / "a" / "proxies.json"));
  EXPECT_EQ(glbA, readBytes(folder_ / "a" / "proxies.glb"));
  // Nothing but the two files is left behind.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder_ / "a")) ++files;
  EXPECT_EQ(files, 2u);
}

TEST_F(RuntimeExport, WorldToUnitMapsBoxCornersToPlusMinusOneAndTheSphereToUnitLength) {
  for (const Runtime& runtime :
       {makeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds()), [&] {
          writeRuntimeExport(roomScene(folder_, UpAxis::Y, 0.01), roomBuilds(), out());
          return readRuntimeExport(out() / "proxies.json");
        }()}) {
    for (int i : {3, 4}) {  // aabb, obb
      const RuntimeProbe& p = runtime.probes[i];
      SCOPED_TRACE(p.name);
      ASSERT_TRUE(p.worldToUnit);
      const ConvexProxy corners = convexFromBox(*p.box);
      for (int c = 0; c < 8; ++c) {
        const glm::dvec4 unit = *p.worldToUnit * glm::dvec4(corners.verticesMeters[c], 1.0);
        const glm::dvec3 expected((c & 1) ? 1 : -1, (c & 2) ? 1 : -1, (c & 4) ? 1 : -1);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(unit[k], expected[k], 1e-12);
        EXPECT_EQ(unit.w, 1.0);
      }
      const glm::dvec4 centre = *p.worldToUnit * glm::dvec4(p.box->centerMeters, 1.0);
      EXPECT_NEAR(glm::length(glm::dvec3(centre)), 0.0, 1e-12);
    }
    const RuntimeProbe& sphere = runtime.probes[2];
    for (const glm::dvec3& v : sphere.convex.verticesMeters) {  // the icosphere lies on it
      const glm::dvec4 unit = *sphere.worldToUnit * glm::dvec4(v, 1.0);
      EXPECT_NEAR(glm::length(glm::dvec3(unit)), 1.0, 1e-12);
    }
  }
}

TEST_F(RuntimeExport, EllipsoidUnitTransformAndIcosphereWinding) {
  const glm::dvec3 center(1, -2, 0.5), radii(0.5, 2.0, 1.25);
  const glm::dquat rotation = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3)));
  const glm::dmat4 m = toUnitTransform(center, radii, rotation);
  const ConvexProxy mesh = icosphereMesh(center, radii, rotation);
  EXPECT_EQ(mesh.verticesMeters.size(), 162u);
  EXPECT_EQ(mesh.triangles.size(), 320u);
  for (const glm::dvec3& v : mesh.verticesMeters) {
    EXPECT_NEAR(glm::length(glm::dvec3(m * glm::dvec4(v, 1.0))), 1.0, 1e-12);
  }
  // The axis ends of the ellipsoid go to the unit axes.
  const glm::dvec3 yEnd = center + rotation * glm::dvec3(0, radii.y, 0);
  const glm::dvec4 unit = m * glm::dvec4(yEnd, 1.0);
  EXPECT_NEAR(unit.x, 0.0, 1e-12);
  EXPECT_NEAR(unit.y, 1.0, 1e-12);
  EXPECT_NEAR(unit.z, 0.0, 1e-12);
  for (const glm::uvec3& t : mesh.triangles) {  // counter-clockwise seen from outside
    const glm::dvec3 a = mesh.verticesMeters[t.x], b = mesh.verticesMeters[t.y],
                     c = mesh.verticesMeters[t.z];
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0 - center), 0.0);
  }
}

// ------------------------------------------------------------------------------------------
// Engines, for known boxes. The room box: centre (0, 0, 1.5), half-extents (3, 2, 1.5),
// capture (1, 0.5, 1.2): box centre - capture = (-1, -0.5, 0.3) m.

// One frame conversion for the scene file, proxies.json and the engines
// (core/scene/file_frame.h). Each frame's rotation conversion is R' = A R A^T, exact: checked
// against the matrix product for a turned box, in a right-handed and a left-handed frame.
TEST_F(RuntimeExport, OneFrameConversionForFilesAndEngines) {
  const glm::dquat q = glm::normalize(glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, 3))));
  for (const FileFrame& frame : {FileFrame(UpAxis::Y, 0.01), FileFrame(UpAxis::Z, 2.0), gltfFrame(),
                                 unityFrame(), unrealFrame()}) {
    // A: file from world, as a matrix, from how points convert.
    glm::dmat3 a(0.0);
    for (int c = 0; c < 3; ++c) {
      glm::dvec3 e(0.0);
      e[c] = 1.0;
      a[c] = fileDirectionFromWorld(frame, e);
    }
    const double det = glm::determinant(a);
    EXPECT_EQ(std::abs(det), 1.0);
    EXPECT_EQ(det, frame.determinant);
    const glm::dmat3 expected = a * glm::mat3_cast(q) * glm::transpose(a);
    const glm::dmat3 got = glm::mat3_cast(fileRotationFromWorld(frame, q));
    for (int c = 0; c < 3; ++c) expectClose(got[c], expected[c], 1e-15);
    // Exact round trips: the axes are a copy and a sign; the unit divides and multiplies.
    const glm::dvec3 p(1.25, -3.5, 0.75);
    EXPECT_EQ(worldDirectionFromFile(frame, fileDirectionFromWorld(frame, p)), p);
    EXPECT_EQ(worldRotationFromFile(frame, fileRotationFromWorld(frame, q)), q);
    // Half-extents are permuted, never negated.
    const glm::dvec3 h = fileHalfExtentsFromWorld(frame, glm::dvec3(1, 2, 3));
    EXPECT_TRUE(glm::all(glm::greaterThan(h, glm::dvec3(0.0))));
  }
  // The frames the engines document: Unity (x, y, z) = world (-x, z, -y); Unreal (x, -y, z) cm.
  expectClose(filePointFromWorld(unityFrame(), {1, 2, 3}), {-1, 3, -2}, 0.0);
  expectClose(filePointFromWorld(unrealFrame(), {1, 2, 3}), {100, -200, 300}, 1e-12);
  expectClose(filePointFromWorld(gltfFrame(), {1, 2, 3}), {1, 3, -2}, 0.0);
}

TEST_F(RuntimeExport, UnityBoxIsLeftHandedYUpRelativeToTheProbeShrunkByItsBlendDistance) {
  const InfluenceVolume influence =
      BoxInfluence{{0, 0, 1.5}, {3.0, 2.0, 1.5}, quat(1, 0, 0, 0), {2.5, 1.5, 1.0}};
  const UnityReflectionProbe u = unityReflectionProbe(kRoomBox, kCapture, influence);
  // Unity (x, y, z) = world (-x, z, -y).
  expectClose(u.position, {-1.0, 1.2, -0.5}, 1e-15);
  // Unity fades outside the box over blendDistance (the influence's 0.5 m fade) and projects on
  // the box grown by it: the full size x 6, height 3, depth 4 less 2 x 0.5 m, but the height
  // only at the top (the bottom, the floor, stays): height 2.5, centre 0.25 m lower.
  EXPECT_EQ(u.blendDistance, 0.5);
  expectClose(u.size, {5.0, 2.5, 3.0}, 1e-15);
  expectClose(u.center, {1.0, 0.05, 0.5}, 1e-15);  // (-(-1), 0.3 - 0.25, -(-0.5))
  EXPECT_TRUE(u.boxProjection);
  // No fade: the smallest Unity can divide by. A wide fade: half the shortest half-extent.
  EXPECT_EQ(
      unityReflectionProbe(kRoomBox, kCapture,
                           BoxInfluence{{0, 0, 1.5}, {3, 2, 1.5}, quat(1, 0, 0, 0), {3, 2, 1.5}})
          .blendDistance,
      kUnityMinBlendMeters);
  EXPECT_EQ(unityReflectionProbe(kRoomBox, kCapture, SphereInfluence{{0, 0, 1.5}, 5.0, 1.0})
                .blendDistance,
            0.75);
}

TEST_F(RuntimeExport, UnrealBoxIsLeftHandedZUpCentimetresWithHalfExtentScale) {
  const InfluenceVolume influence =
      BoxInfluence{{0, 0, 1.5}, {3.0, 2.0, 1.5}, quat(1, 0, 0, 0), {2.5, 1.5, 1.0}};
  const UnrealBoxReflectionCapture u = unrealBoxReflectionCapture(kRoomBox, kCapture, influence);
  // Unreal (x, y, z) = world (x, -y, z) * 100.
  expectClose(u.location, {0.0, 0.0, 150.0}, 0.0);
  expectClose(u.scale3D, {300.0, 200.0, 150.0}, 0.0);  // half-extents in cm
  expectClose(u.captureOffset, {100.0, -50.0, -30.0}, 1e-13);
  expectClose(u.rotation, quat(1, 0, 0, 0), 0.0);
  EXPECT_DOUBLE_EQ(u.boxTransitionDistance, 50.0);  // outer - inner = 0.5 m on every axis

  // A box turned 90 degrees about world +Z (its own x along world +y): in Unreal, whose Y is
  // flipped, that is -90 degrees about Z.
  const BoxShape turned{{2.0, -1.0, 1.0}, {1.0, 2.0, 0.5}, aboutZ(90.0)};
  const UnrealBoxReflectionCapture t =
      unrealBoxReflectionCapture(turned, {2.5, -1.0, 1.0}, influence);
  expectClose(t.location, {200.0, 100.0, 100.0}, 0.0);
  expectClose(t.scale3D, {100.0, 200.0, 50.0}, 0.0);
  expectClose(t.captureOffset, {50.0, 0.0, 0.0}, 0.0);
  expectClose(t.rotation, quat(kHalfSqrt2, 0, 0, -kHalfSqrt2), 1e-15);
  const glm::dvec3 ownX = t.rotation * glm::dvec3(1, 0, 0);  // world +y is Unreal -y
  expectClose(ownX, {0.0, -1.0, 0.0}, 1e-15);
}

TEST_F(RuntimeExport, UnrealSphereTakesTheInfluenceRadiusInCentimetres) {
  const SphereShape sphere{{0.0, 0.0, 1.5}, glm::dvec3(3.0), quat(1, 0, 0, 0)};
  const UnrealSphereReflectionCapture u = unrealSphereReflectionCapture(sphere, kCapture);
  expectClose(u.location, {0.0, 0.0, 150.0}, 0.0);
  EXPECT_EQ(u.influenceRadius, 300.0);
  expectClose(u.captureOffset, {100.0, -50.0, -30.0}, 1e-13);
}

TEST_F(RuntimeExport, GodotBoxIsYUpFullSizeWithALocalOriginOffset) {
  const InfluenceVolume influence =
      BoxInfluence{{0, 0, 1.5}, {3.0, 2.0, 1.5}, quat(1, 0, 0, 0), {1.2, 2.0, 1.5}};
  const GodotReflectionProbe g = godotReflectionProbe(kRoomBox, kCapture, influence);
  // Godot (x, y, z) = world (x, z, -y).
  expectClose(g.origin, {0.0, 1.5, 0.0}, 0.0);
  expectClose(g.size, {6.0, 3.0, 4.0}, 0.0);
  expectClose(g.originOffset, {1.0, -0.3, -0.5}, 1e-15);
  expectClose(g.rotation, quat(1, 0, 0, 0), 0.0);
  EXPECT_TRUE(g.boxProjection);
  EXPECT_TRUE(g.exact);
  EXPECT_DOUBLE_EQ(g.blendDistance, 1.8);  // the influence fades along x only: 3 - 1.2 m

  // Turned 90 degrees about world +Z = 90 degrees about Godot +Y; the capture point 0.5 m
  // along world +x is 0.5 m along the node's own +z.
  const BoxShape turned{{2.0, -1.0, 1.0}, {1.0, 2.0, 0.5}, aboutZ(90.0)};
  const GodotReflectionProbe t = godotReflectionProbe(turned, {2.5, -1.0, 1.0}, influence);
  expectClose(t.origin, {2.0, 1.0, 1.0}, 0.0);
  expectClose(t.size, {2.0, 1.0, 4.0}, 0.0);
  expectClose(t.rotation, quat(kHalfSqrt2, 0, kHalfSqrt2, 0), 1e-15);
  expectClose(t.originOffset, {0.0, 0.0, 0.5}, 1e-15);
  EXPECT_TRUE(t.exact);
  // Godot keeps origin_offset 1 cm inside the box: a capture point on a face is not exact.
  EXPECT_FALSE(godotReflectionProbe(kRoomBox, {3.0, 0.0, 1.5}, influence).exact);
}

TEST_F(RuntimeExport, BevyScalesAUnitCubeAndNeedsTheCaptureAtItsCentre) {
  const InfluenceVolume fade{
      BoxInfluence{{0, 0, 1.5}, {3.0, 2.0, 1.5}, quat(1, 0, 0, 0), {2.5, 2.0, 1.5}}};  // 0.5 m
  const BevyLightProbe b = bevyLightProbe(kRoomBox, kCapture, fade);
  expectClose(b.translation, {0.0, 1.5, 0.0}, 0.0);
  expectClose(b.scale, {6.0, 3.0, 4.0}, 0.0);
  // falloff * scale / 2 = 0.5 m on every axis.
  expectClose(b.falloff, {0.5 / 3.0, 0.5 / 1.5, 0.5 / 2.0}, 1e-15);
  EXPECT_FALSE(b.captureAtCentre);
  EXPECT_FALSE(b.exact);
  // At the centre, but a 6 x 3 x 4 box: Bevy looks up in the scaled cube, not exact.
  const BevyLightProbe centred = bevyLightProbe(kRoomBox, kRoomBox.centerMeters, fade);
  EXPECT_TRUE(centred.captureAtCentre);
  EXPECT_FALSE(centred.exact);
  // A cube, not turned, captured at its centre: exact.
  const BoxShape cube{{1.0, 2.0, 3.0}, {2.0, 2.0, 2.0}, quat(1, 0, 0, 0)};
  EXPECT_TRUE(bevyLightProbe(cube, cube.centerMeters, fade).exact);
  // The same cube turned 30 degrees about Z: the lookup is in the turned axes, not exact.
  const BoxShape turned{cube.centerMeters, cube.halfExtentsMeters,
                        glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 0, 1))};
  EXPECT_FALSE(bevyLightProbe(turned, turned.centerMeters, fade).exact);
}

// The transition distance is the smallest fade over the axes that fade; the old
// rule (the smallest over all three axes) gave 0, a hard cut, on rooms fading along one axis.
TEST_F(RuntimeExport, TransitionDistanceIsTheSmallestFadeOverTheAxesThatFade) {
  const auto box = [](glm::dvec3 inner) {
    return InfluenceVolume{BoxInfluence{{0, 0, 0}, {5.0, 2.0, 1.5}, quat(1, 0, 0, 0), inner}};
  };
  EXPECT_DOUBLE_EQ(transitionDistanceMeters(box({3.55, 2.0, 1.5})), 1.45);  // l_room's arm_x
  EXPECT_DOUBLE_EQ(transitionDistanceMeters(box({4.0, 1.5, 1.5})), 0.5);    // x 1, y 0.5
  EXPECT_EQ(transitionDistanceMeters(box({5.0, 2.0, 1.5})), 0.0);           // no fade at all
  EXPECT_DOUBLE_EQ(transitionDistanceMeters(SphereInfluence{{0, 0, 0}, 3.0, 2.25}), 0.75);
  const UnrealBoxReflectionCapture u =
      unrealBoxReflectionCapture(kRoomBox, kCapture, box({3.55, 2.0, 1.5}));
  EXPECT_DOUBLE_EQ(u.boxTransitionDistance, 145.0);  // cm
}

// A box given as six planes is found again, to the identity rotation when axis-aligned.
TEST_F(RuntimeExport, KeptBoxFindsTheBoxInSixPlanes) {
  const std::optional<BoxShape> aligned = boxOfConvex(convexFromBox(kRoomBox));
  ASSERT_TRUE(aligned);
  EXPECT_EQ(methodId(ProxyShape(*aligned)), "aabb");
  expectClose(aligned->centerMeters, kRoomBox.centerMeters, 1e-15);
  expectClose(aligned->halfExtentsMeters, kRoomBox.halfExtentsMeters, 1e-15);

  const BoxShape turned{{2.0, -1.0, 1.0}, {1.0, 2.0, 0.5}, aboutZ(30.0)};
  const std::optional<BoxShape> oriented = boxOfConvex(convexFromBox(turned));
  ASSERT_TRUE(oriented);
  EXPECT_EQ(methodId(ProxyShape(*oriented)), "obb");
  const std::vector<glm::dvec3> a = convexFromBox(turned).verticesMeters;
  const std::vector<glm::dvec3> b = convexFromBox(*oriented).verticesMeters;
  for (const glm::dvec3& p : a) {
    double nearest = INFINITY;
    for (const glm::dvec3& q : b) nearest = std::min(nearest, glm::distance(p, q));
    EXPECT_LE(nearest, 1e-12);
  }
  // Shuffled planes, one pair's offsets moved: still a box, the new one.
  ConvexProxy shuffled = convexFromBox(kRoomBox);
  std::reverse(shuffled.planes.begin(), shuffled.planes.end());
  shuffled.planes[0].offsetMeters += 0.25;
  const std::optional<BoxShape> moved = boxOfConvex(shuffled);
  ASSERT_TRUE(moved);
  EXPECT_NEAR(moved->halfExtentsMeters.z, 1.625, 1e-12);

  // Not boxes: eight planes; six with one wall tilted by 1e-4 rad (corners move 0.2 mm,
  // beyond the 1 um tolerance); a wedge whose pairs are not opposite.
  EXPECT_FALSE(boxOfConvex(chamferedRoom()));
  ConvexProxy tilted = convexFromBox(kRoomBox);
  tilted.planes[0].normal = glm::normalize(glm::dvec3(1.0, 1e-4, 0.0));
  EXPECT_FALSE(boxOfConvex(tilted));
  ConvexProxy wedge = convexFromBox(kRoomBox);
  wedge.planes[4].normal = glm::normalize(glm::dvec3(0.0, 1.0, 1.0));
  EXPECT_FALSE(boxOfConvex(wedge));
  EXPECT_FALSE(keptBox(SphereShape{}));
  EXPECT_TRUE(keptBox(kRoomBox));
}

TEST_F(RuntimeExport, EnginesTakeTheKeptBoxElseTheBestBoxAndUnityAnAabb) {
  const Runtime runtime = makeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds());
  // Kept infinite: no box to keep, so the best of each kind, marked as not the kept proxy.
  const RuntimeEngines& e = runtime.probes[0].engines;
  ASSERT_TRUE(e.unity && e.unrealBox && e.unrealSphere && e.godot && e.bevy);
  EXPECT_EQ(e.unity->source.candidate, "aabb");  // Unity's boxes are axis-aligned
  EXPECT_EQ(e.unity->source.error.p95Deg, 0.5);
  EXPECT_FALSE(e.unity->source.keptProxy);
  EXPECT_EQ(e.unrealBox->source.candidate, "obb");  // p95 0.4 < 0.5
  EXPECT_FALSE(e.unrealBox->source.keptProxy);
  EXPECT_EQ(e.godot->source.candidate, "obb");
  EXPECT_EQ(e.bevy->source.candidate, "obb");
  EXPECT_EQ(e.unrealSphere->source.candidate, "sphere");
  // The obb turned 30 degrees about Z: Godot turns it 30 degrees about +Y.
  expectClose(e.godot->rotation, glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 1, 0)), 1e-15);

  // Kept aabb: every box engine takes it, though the obb's p95 is lower.
  const RuntimeEngines& aabb = runtime.probes[3].engines;
  for (const EngineSource* s :
       {&aabb.unity->source, &aabb.unrealBox->source, &aabb.godot->source, &aabb.bevy->source}) {
    EXPECT_EQ(s->candidate, "aabb");
    EXPECT_TRUE(s->keptProxy);
  }
  // Kept obb: Unity cannot turn a box, so it keeps the best aabb and says it is not the kept.
  const RuntimeEngines& obb = runtime.probes[4].engines;
  EXPECT_EQ(obb.unrealBox->source.candidate, "obb");
  EXPECT_TRUE(obb.unrealBox->source.keptProxy);
  EXPECT_EQ(obb.unity->source.candidate, "aabb");
  EXPECT_FALSE(obb.unity->source.keptProxy);
  // Kept convex_8 (not a box): as before.
  EXPECT_EQ(runtime.probes[5].engines.unrealBox->source.candidate, "obb");
  EXPECT_FALSE(runtime.probes[5].engines.unrealBox->source.keptProxy);

  // A kept convex that is the room box: the engines get that box with its error.
  std::vector<ProbeProxyBuild> convexBuilds = roomBuilds();
  convexBuilds[5].candidates[5] = {CandidateOrigin::Simplified,
                                   convexFromBox(kRoomBox),
                                   figures(0.0, 1e-5, 1e-4, 0.0, 4096),
                                   {},
                                   0.5};
  const Runtime convex = makeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), convexBuilds);
  const RuntimeEngines& c6 = convex.probes[5].engines;
  EXPECT_EQ(c6.unrealBox->source.candidate, "convex_6");
  EXPECT_TRUE(c6.unrealBox->source.keptProxy);
  EXPECT_EQ(c6.unrealBox->source.error.p95Deg, 1e-5);
  // The room box, its bottom 2 cm under the floor it stands on (Unreal's cm, half extents).
  expectClose(c6.unrealBox->scale3D, {300.0, 200.0, 151.0}, 1e-12);
  EXPECT_EQ(c6.unity->source.candidate, "convex_6");
  // The room's size, shrunk on every side by the blend distance Unity grows it by again.
  const double b = c6.unity->blendDistance;
  expectClose(c6.unity->size + glm::dvec3(2.0 * b, b, 2.0 * b), {6.0, 3.02, 4.0}, 1e-14);
  EXPECT_TRUE(c6.unityHdrp && c6.eevee);
  EXPECT_EQ(c6.eevee->source.candidate, "convex_6");

  // Without boxes or spheres, the engines have nothing.
  std::vector<ProbeProxyBuild> builds = roomBuilds();
  builds[0].candidates.resize(2);  // infinite, cheap_k
  builds[0].kept = 1;
  const Runtime bare = makeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), builds);
  const RuntimeEngines& none = bare.probes[0].engines;
  EXPECT_FALSE(none.unity || none.unityHdrp || none.unrealBox || none.unrealSphere || none.godot ||
               none.bevy || none.eevee);
}

// ------------------------------------------------------------------------------------------

TEST_F(RuntimeExport, GlbHoldsOneNamedProxyPerProbeWithAVolume) {
  const Scene scene = roomScene(folder_, UpAxis::Z, 1.0);
  writeRuntimeExport(scene, roomBuilds(), out());
  const Runtime made = makeRuntimeExport(scene, roomBuilds());
  const LevelMesh glb = loadLevelMeshFile(out() / "proxies.glb", UpAxis::Y, 1.0);
  ASSERT_EQ(glb.parts.size(), 4u);  // infinite and cheap_k have no volume
  const int withVolume[] = {2, 3, 4, 5};
  for (std::size_t i = 0; i < 4; ++i) {
    const RuntimeProbe& p = made.probes[withVolume[i]];
    const LevelPart& part = glb.parts[i];
    EXPECT_EQ(part.name, p.name + "_proxy");
    ASSERT_EQ(part.triangleCount, p.convex.triangles.size());
    for (std::uint32_t t = 0; t < part.triangleCount; ++t) {  // same corners, same winding
      for (int k = 0; k < 3; ++k) {
        const glm::dvec3 read(glb.positionsMeters[glb.triangles[part.firstTriangle + t][k]]);
        const glm::dvec3 written = p.convex.verticesMeters[p.convex.triangles[t][k]];
        EXPECT_NEAR(glm::distance(read, written), 0.0, 1e-6);
      }
    }
  }
}

TEST_F(RuntimeExport, NoVolumeAtAllStillWritesAValidGlb) {
  std::vector<ProbeProxyBuild> builds = roomBuilds();
  builds.resize(2);  // keep_infinite, keep_cheap_k
  writeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), builds, out());
  const std::string glb = readBytes(out() / "proxies.glb");
  ASSERT_GE(glb.size(), 20u);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(glb.size() % 4, 0u);
  EXPECT_EQ(readRuntimeExport(out() / "proxies.json").probes.size(), 2u);
}

// ------------------------------------------------------------------------------------------
// Refusals: nothing an artist made is overwritten, and nothing is written instead.

TEST_F(RuntimeExport, RefusesAProxiesJsonThatIsNotOurs) {
  const fs::path foreign = write("export/proxies.json", R"({"probes": "the artist's own"})");
  try {
    writeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds(), out());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              foreign.string() +
                  ": exists and is not a probeproxy runtime export (no \"probeproxy_runtime\" "
                  "member); refusing to overwrite it (move it away or export to another folder)");
  }
  EXPECT_EQ(readBytes(foreign), R"({"probes": "the artist's own"})");
  EXPECT_FALSE(fs::exists(out() / "proxies.glb"));
}

TEST_F(RuntimeExport, RefusesAProxiesGlbWithoutOurJsonBesideIt) {
  const fs::path glb = write("export/proxies.glb", "artist mesh");
  try {
    writeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds(), out());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              glb.string() +
                  ": exists without a probeproxy proxies.json beside it; refusing to "
                  "overwrite it (move it away or export to another folder)");
  }
  EXPECT_EQ(readBytes(glb), "artist mesh");
  EXPECT_FALSE(fs::exists(out() / "proxies.json"));
}

TEST_F(RuntimeExport, RefusesToOverwriteTheSceneFileOrALevelMesh) {
  Scene scene = roomScene(folder_, UpAxis::Z, 1.0);
  scene.file = write("export/proxies.json", R"({"probeproxy_scene": 1})");
  try {
    writeRuntimeExport(scene, roomBuilds(), out());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (out() / "proxies.json").string() +
                  ": is the scene file; refusing to overwrite it (export to another folder)");
  }
  EXPECT_EQ(readBytes(scene.file), R"({"probeproxy_scene": 1})");
  EXPECT_FALSE(fs::exists(out() / "proxies.glb"));
  fs::remove(scene.file);

  scene = roomScene(folder_, UpAxis::Z, 1.0);
  scene.level.push_back(
      {out() / "sub" / ".." / "proxies.glb", "export/proxies.glb", UpAxis::Y, false, {}});
  try {
    writeRuntimeExport(scene, roomBuilds(), out());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (out() / "proxies.glb").string() +
                  ": is a level mesh of the scene; refusing to overwrite it (export to another "
                  "folder)");
  }
  EXPECT_FALSE(fs::exists(out() / "proxies.json"));
}

TEST_F(RuntimeExport, AFailedWriteLeavesThePreviousExportWhole) {
  const Scene scene = roomScene(folder_, UpAxis::Z, 1.0);
  writeRuntimeExport(scene, roomBuilds(), out());
  const std::string before = readBytes(out() / "proxies.json");
  // proxies.glb cannot be replaced: a folder stands in its place.
  fs::remove(out() / "proxies.glb");
  write("export/proxies.glb/keep.txt", "x");
  std::vector<ProbeProxyBuild> builds = roomBuilds();
  builds.resize(3);
  EXPECT_THROW(writeRuntimeExport(scene, builds, out()), InputError);
  EXPECT_EQ(readBytes(out() / "proxies.json"), before);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(out())) left.push_back(entry.path().filename());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"proxies.glb", "proxies.json"}));  // no staged files
}

TEST_F(RuntimeExport, BrokenBuildsAreAProgrammingError) {
  const Scene scene = roomScene(folder_, UpAxis::Z, 1.0);
  std::vector<ProbeProxyBuild> builds = roomBuilds();
  builds[0].kept = 6;
  EXPECT_THROW(makeRuntimeExport(scene, builds), std::invalid_argument);
  builds = roomBuilds();
  builds[1].probe = "nowhere";
  EXPECT_THROW(makeRuntimeExport(scene, builds), std::invalid_argument);
  builds = roomBuilds();
  std::get<BoxShape>(builds[2].candidates[3].shape).halfExtentsMeters.x = kNaN;
  EXPECT_THROW(writeRuntimeExport(scene, builds, out()), std::invalid_argument);
  EXPECT_FALSE(fs::exists(out()));
}

// ------------------------------------------------------------------------------------------
// Bad proxies.json: one line naming the file and the JSON path.

class RuntimeExportBadInput : public RuntimeExport {
 protected:
  // The good file with its first `from` replaced by `to`; what reading it says.
  std::string problemAfter(const std::string& from, const std::string& to) {
    writeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds(), out());
    std::string json = readBytes(out() / "proxies.json");
    const std::size_t at = json.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at == std::string::npos) return "";
    json.replace(at, from.size(), to);
    const fs::path edited = write("edited.json", json);
    try {
      readRuntimeExport(edited);
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), edited);
      EXPECT_EQ(std::string(e.what()), edited.string() + ": " + e.problem());
      return e.problem();
    }
    ADD_FAILURE() << "no InputError";
    return "";
  }
};

TEST_F(RuntimeExportBadInput, MissingMemberNamesItsObject) {
  EXPECT_EQ(problemAfter(R"("capture": [1.0, 0.5, 1.2],)", ""),
            "$.probes[0]: expected member \"capture\"");
  EXPECT_EQ(problemAfter(R"("samples": 0)", R"("sample": 0)"),
            "$.probes[0].error: expected member \"samples\"");
}

TEST_F(RuntimeExportBadInput, WrongTypeNamesTheValue) {
  EXPECT_EQ(problemAfter(R"("capture": [1.0, 0.5, 1.2])", R"("capture": "a")"),
            "$.probes[0].capture: expected an array of 3 finite numbers, got \"a\"");
  EXPECT_EQ(problemAfter(R"("capture": [1.0, 0.5, 1.2])", R"("capture": [1.0, "x", 1.2])"),
            "$.probes[0].capture[1]: expected a finite number, got \"x\"");
  EXPECT_EQ(problemAfter(R"("kind": "cheap_k")", R"("kind": "box")"),
            "$.probes[1].kind: expected one of \"infinite\", \"cheap_k\", \"sphere\", \"aabb\", "
            "\"obb\", \"convex\", got \"box\"");
  EXPECT_EQ(problemAfter(R"("planes_count": 0)", R"("planes_count": -1)"),
            "$.probes[0].planes_count: expected a non-negative integer, got -1");
  EXPECT_EQ(problemAfter(R"("box_projection": true)", R"("box_projection": 1)"),
            "$.probes[0].engines.unity_reflection_probe.box_projection: expected true or false, "
            "got 1");
  EXPECT_EQ(problemAfter(R"("importance": 1)", R"("importance": 1.5)"),
            "$.probes[0].engines.unity_reflection_probe.importance: expected an integer (a 32-bit "
            "int), got 1.5");
  EXPECT_EQ(problemAfter(R"("importance": 1)", R"("importance": 3000000000)"),
            "$.probes[0].engines.unity_reflection_probe.importance: expected an integer (a 32-bit "
            "int), got 3000000000");
  const glm::uvec3 first = makeRuntimeExport(roomScene(folder_, UpAxis::Z, 1.0), roomBuilds())
                               .probes[2]
                               .convex.triangles[0];
  const std::string a = std::to_string(first.x), b = std::to_string(first.y);
  EXPECT_EQ(problemAfter("[" + a + ", " + b + ", " + std::to_string(first.z) + "],",
                         "[" + a + ", " + b + ", 300],"),
            "$.probes[2].triangles[0]: expected vertex indices below 162, got [" + a + ", " + b +
                ", 300]");
}

TEST_F(RuntimeExportBadInput, NotOurFormatOrNotJson) {
  EXPECT_EQ(problemAfter(R"("probeproxy_runtime": 1)", R"("probeproxy_runtime": 2)"),
            "$.probeproxy_runtime: expected 1, got 2");
  EXPECT_EQ(problemAfter(R"("probeproxy_runtime": 1)", R"("probeproxy_scene": 1)"),
            "$: expected member \"probeproxy_runtime\"");
  const std::string truncated = problemAfter("\n  \"probes\"", "\n  \"probes");
  EXPECT_EQ(truncated.rfind("invalid JSON at line", 0), 0u) << truncated;
}

}  // namespace
}  // namespace probeproxy::runtime_export_test
