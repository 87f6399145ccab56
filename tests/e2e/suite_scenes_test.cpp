// Every level of the Blender suite, read through probeproxy's own readers, and the proof that
// Blender's renders and probeproxy's ray caster use the same cube-face convention: the suite
// renders each probe's cube a second time with every surface emitting its world position, so
// each texel of that render must equal the point our depth cube puts at the same texel.

#include "core/cube/cubemap_io.h"
#include "core/cube/write_depth_cube.h"
#include "geometry/export/kept_box.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/load_level.h"
#include "geometry/probe_proxies/build_scene_proxies.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/scene/scene_file.h"
#include "geometry/validate/proxy_mesh_checks.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <filesystem>

namespace probeproxy {
namespace {

const std::filesystem::path kSuite = PROBEPROXY_SUITE_DIR;

const std::vector<std::string> kLevels = {"corridor",     "l_room",      "u_corridors",
                                          "hall_pillars", "attic",       "round_room",
                                          "courtyard",    "tiny_closet", "hangar"};

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;
};

Image readImage(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error("cannot open " + file.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image image{spec.width, spec.height, spec.nchannels, {}};
  image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * image.channels);
  if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    throw std::runtime_error("cannot read " + file.string() + ": " + in->geterror());
  }
  return image;
}

class SuiteLevel : public ::testing::TestWithParam<std::string> {
 protected:
  std::filesystem::path sceneFile() const {
    return kSuite / GetParam() / (GetParam() + ".scene.json");
  }
  // The same level with the artist's axis-aligned boxes as authored proxies, for the levels
  // whose main scene file asks for `auto` (the box is a poor proxy there).
  std::filesystem::path artistSceneFile() const {
    return kSuite / GetParam() / (GetParam() + ".artist.scene.json");
  }
};

TEST_P(SuiteLevel, SceneAndLevelLoad) {
  const Scene scene = readSceneFile(sceneFile());
  EXPECT_FALSE(scene.probes.empty());
  const LevelMesh level = loadLevel(scene);
  EXPECT_GT(level.triangles.size(), 10u);
  for (const Probe& probe : scene.probes) {
    ASSERT_TRUE(probe.cubemap.has_value()) << probe.name;
    // Through the core's own cubemap reader: six square faces of one size, finite, mips built.
    const Cubemap cube = readCubemap((scene.file.parent_path() / *probe.cubemap).string());
    EXPECT_EQ(cube.faceSize(0), 64) << probe.name;
    EXPECT_EQ(cube.numLevels(), fullMipCount(64)) << probe.name;
  }
}

TEST_P(SuiteLevel, BlenderCubesUseTheCoreFaceConvention) {
  const Scene scene = readSceneFile(sceneFile());
  const LevelRayCaster caster(loadLevel(scene));
  for (const Probe& probe : scene.probes) {
    std::vector<double> errors;
    std::size_t sky = 0, skyAgreed = 0;
    for (int f = 0; f < kCubeFaceCount; ++f) {
      const std::string pattern = "cubemaps/" + probe.name + "_position_{face}.exr";
      const Image blender =
          readImage(scene.file.parent_path() / cubeFacePath(pattern, CubeFace(f)));
      const int n = blender.width;
      const DepthCube cube = captureDepthCube(caster, probe.captureMeters, n);
      for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
          const float* p =
              &blender.pixels[(static_cast<std::size_t>(row) * n + col) * blender.channels];
          const float t = cube.at(CubeFace(f), col, row);
          if (std::isinf(t)) {
            ++sky;
            skyAgreed += p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f;
            continue;
          }
          const glm::dvec3 ours = probe.captureMeters +
                                  double(t) * glm::dvec3(texelDirection(CubeFace(f), col, row, n));
          errors.push_back(glm::distance(ours, glm::dvec3(p[0], p[1], p[2])));
        }
      }
    }
    ASSERT_FALSE(errors.empty());
    // Texels on a silhouette may see different surfaces at their centre and their samples;
    // everything else must agree to a millimetre. A mirrored or rotated face fails by metres.
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2];
    const double p99 = errors[errors.size() * 99 / 100];
    EXPECT_LT(median, 1e-3) << probe.name;
    EXPECT_LT(p99, 0.05) << probe.name;
    EXPECT_GE(skyAgreed, sky * 95 / 100)
        << probe.name << ": sky texels that Blender saw a surface in";
  }
}

// The proxies' bars, on every level: each kept proxy contains its capture point and passes the
// OpenMesh checks; convex rooms are modelled to a quarter degree; concave rooms never do worse
// than the artist's box, with fewer than 32 planes; the export reads back to the same values.
TEST_P(SuiteLevel, BuiltProxiesAreValidAndAccurate) {
  const Scene scene = readSceneFile(sceneFile());
  const LevelRayCaster caster(loadLevel(scene));
  const bool convexRoom = GetParam() == "corridor" || GetParam() == "round_room" ||
                          GetParam() == "tiny_closet" || GetParam() == "hangar";
  const bool concaveRoom = GetParam() == "l_room" || GetParam() == "hall_pillars" ||
                           GetParam() == "attic" || GetParam() == "u_corridors";
  // Where the main scene asks for `auto`, build its artist variant with --regenerate: the
  // same probes and volumes, so the same generated candidates and kept proxy, with the artist
  // box measured beside them as the `authored` candidate.
  const bool hasArtist = std::filesystem::exists(artistSceneFile());
  EXPECT_EQ(hasArtist,
            !(GetParam() == "corridor" || GetParam() == "tiny_closet" || GetParam() == "hangar"));
  const Scene measured = hasArtist ? readSceneFile(artistSceneFile()) : scene;
  ASSERT_EQ(measured.probes.size(), scene.probes.size());
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    const Probe& main = scene.probes[i];
    const Probe& artist = measured.probes[i];
    EXPECT_EQ(main.name, artist.name);
    EXPECT_EQ(main.captureMeters, artist.captureMeters) << main.name;
    glm::dvec3 mainMin, mainMax, artistMin, artistMax;
    influenceBounds(main.influence, mainMin, mainMax);
    influenceBounds(artist.influence, artistMin, artistMax);
    EXPECT_EQ(main.influence.index(), artist.influence.index()) << main.name;
    EXPECT_TRUE(mainMin == artistMin && mainMax == artistMax) << main.name;
    EXPECT_EQ(main.cubemap, artist.cubemap) << main.name;
    EXPECT_EQ(std::holds_alternative<AutoProxy>(main.proxy), hasArtist) << main.name;
    EXPECT_TRUE(std::holds_alternative<AuthoredBox>(artist.proxy)) << main.name;
  }
  ProxyBuildOptions options;
  options.regenerate = true;
  const std::vector<ProbeProxyBuild> builds = buildSceneProxies(measured, caster, options);
  for (std::size_t i = 0; i < builds.size(); ++i) {
    const ProbeProxyBuild& b = builds[i];
    const ProxyCandidate& kept = b.candidates[b.kept];
    const glm::dvec3 capture = scene.probes[i].captureMeters;
    // The one finding a suite probe may get says its kept proxy misses the tolerance, and it
    // comes exactly when it does (an L's corner, a pillared hall and an open court do).
    const bool missesTolerance =
        !(kept.error.p95Deg <= options.toleranceDeg && kept.error.missRate <= options.maxMissRate);
    bool saysSo = false;
    for (const std::string& f : b.findings) {
      const bool overTolerance = f.rfind("kept ", 0) == 0;
      EXPECT_TRUE(overTolerance) << b.probe << ": " << f;
      saysSo = saysSo || overTolerance;
    }
    EXPECT_EQ(saysSo, missesTolerance) << b.probe << ": p95 " << kept.error.p95Deg;
    EXPECT_TRUE(strictlyContains(kept.shape, capture)) << b.probe;
    const ConvexProxy convex =
        std::holds_alternative<BoxShape>(kept.shape) ? convexFromBox(std::get<BoxShape>(kept.shape))
        : std::get_if<ConvexProxy>(&kept.shape)      ? std::get<ConvexProxy>(kept.shape)
                                                     : ConvexProxy{};
    if (!convex.planes.empty()) {
      for (const ProxyMeshFinding& f : checkConvexProxy(convex, capture))
        ADD_FAILURE() << b.probe << ": " << f.message;
    }
    EXPECT_EQ(kept.error.missRate, 0.0) << b.probe;
    if (convexRoom) {
      EXPECT_LT(kept.error.p95Deg, 0.25) << b.probe;
    }
    if (concaveRoom) {
      const ErrorFigures& artist = b.candidates.front().error;
      ASSERT_EQ(b.candidates.front().origin, CandidateOrigin::Authored);
      EXPECT_LE(kept.error.p95Deg, artist.p95Deg + 0.01) << b.probe;
      EXPECT_LE(kept.error.medianDeg, artist.medianDeg + 0.005) << b.probe;
      EXPECT_LT(planeCount(kept.shape), 32) << b.probe;
      // Where one convex room does model what the probe sees (an L's arm, a U's leg, the
      // attic), the kept proxy's planes are the level's own walls, not texel-tilted hull
      // facets: float noise only, where the artist box is off by tens of degrees.
      const bool convexPart = b.probe == "arm_x" || b.probe == "arm_y" ||
                              b.probe == "ground_south" || b.probe == "ground_north" ||
                              b.probe == "upper_south" || b.probe == "upper_north" ||
                              b.probe.rfind("attic_", 0) == 0;
      if (convexPart) {
        EXPECT_LT(kept.error.p95Deg, 1e-3) << b.probe;
        EXPECT_GT(artist.p95Deg, 20.0) << b.probe;
      }
    }
  }

  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "probeproxy-suite-export" / GetParam();
  std::filesystem::remove_all(out);
  writeRuntimeExport(scene, builds, out);
  const RuntimeExport back = readRuntimeExport(out / "proxies.json");
  ASSERT_EQ(back.probes.size(), builds.size());
  for (std::size_t i = 0; i < builds.size(); ++i) {
    EXPECT_EQ(back.probes[i].name, builds[i].probe);
    EXPECT_EQ(back.probes[i].planesCount, planeCount(builds[i].candidates[builds[i].kept].shape));
  }
  const LevelMesh glb = loadLevelMeshFile(out / "proxies.glb", UpAxis::Y, scene.metersPerUnit);
  EXPECT_EQ(glb.parts.size(), builds.size());
  std::filesystem::remove_all(out);
}

// The engines get the kept proxy. On every probe whose kept proxy is a box, each box
// engine's preset, read back from proxies.json and turned into world corners with the engine's
// own formula (written out here from the engine's documentation, not through our frames),
// is the kept box: its corners within 1 um (+ the 1e-9 engine-unit rounding) of the kept
// proxy's, and its error figures are the kept proxy's.
std::vector<glm::dvec3> boxCorners(glm::dvec3 center, const glm::dquat& rotation,
                                   glm::dvec3 halfExtents) {
  std::vector<glm::dvec3> corners;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 s((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    corners.push_back(center + rotation * (s * halfExtents));
  }
  return corners;
}

double cornerDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  double worst = 0.0;
  for (const auto* from : {&a, &b}) {
    const auto& to = from == &a ? b : a;
    for (const glm::dvec3& p : *from) {
      double nearest = INFINITY;
      for (const glm::dvec3& q : to) nearest = std::min(nearest, glm::distance(p, q));
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}

TEST_P(SuiteLevel, EnginePresetsAreTheKeptBox) {
  const Scene scene = readSceneFile(sceneFile());
  const LevelRayCaster caster(loadLevel(scene));
  const std::vector<ProbeProxyBuild> builds = buildSceneProxies(scene, caster, ProxyBuildOptions{});
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / "probeproxy-suite-engines" / GetParam();
  std::filesystem::remove_all(out);
  writeRuntimeExport(scene, builds, out);
  const RuntimeExport back = readRuntimeExport(out / "proxies.json");
  std::filesystem::remove_all(out);
  constexpr double kTolerance = kBoxCornerToleranceMeters + 1e-8;
  ASSERT_EQ(back.probes.size(), builds.size());
  for (std::size_t i = 0; i < builds.size(); ++i) {
    const ProbeProxyBuild& b = builds[i];
    const ProxyCandidate& kept = b.candidates[b.kept];
    const RuntimeEngines& e = back.probes[i].engines;
    const std::optional<BoxShape> box = keptBox(kept.shape);
    // The rooms of the issue: a kept convex_6 that is the room is a box.
    const bool issueRoom = b.probe == "arm_x" || b.probe == "arm_y" || b.probe == "ground_south" ||
                           b.probe == "ground_north" || b.probe == "upper_south" ||
                           b.probe == "upper_north";
    if (issueRoom) {
      EXPECT_TRUE(box.has_value()) << b.probe << " kept " << candidateName(kept);
    }
    if (!box) {
      if (e.unrealBox) {
        EXPECT_FALSE(e.unrealBox->source.keptProxy) << b.probe;
      }
      continue;
    }
    // Every engine's box is the kept one, its bottom 2 cm under the floor (runtime_export.h).
    const std::vector<glm::dvec3> keptCorners =
        convexFromBox(withBottomLowered(*box, kFloorClearanceMeters)).verticesMeters;
    ASSERT_EQ(keptCorners.size(), 8u) << b.probe;

    // Unreal: a unit box (extent 1) under location, rotation and scale (= half-extents), cm,
    // left-handed Z up: world = (x, -y, z) / 100.
    ASSERT_TRUE(e.unrealBox) << b.probe;
    std::vector<glm::dvec3> unreal;
    for (const glm::dvec3& c :
         boxCorners(e.unrealBox->location, e.unrealBox->rotation, e.unrealBox->scale3D)) {
      unreal.push_back(glm::dvec3(c.x, -c.y, c.z) / 100.0);
    }
    EXPECT_LE(cornerDistance(unreal, keptCorners), kTolerance) << b.probe << " unreal";
    // Godot: a box of full `size` centred on the node, glTF axes: world = (x, -z, y).
    ASSERT_TRUE(e.godot) << b.probe;
    std::vector<glm::dvec3> godot;
    for (const glm::dvec3& c : boxCorners(e.godot->origin, e.godot->rotation, e.godot->size / 2.0))
      godot.push_back({c.x, -c.z, c.y});
    EXPECT_LE(cornerDistance(godot, keptCorners), kTolerance) << b.probe << " godot";
    // Bevy: the unit cube (1 x 1 x 1) under the Transform, glTF axes.
    ASSERT_TRUE(e.bevy) << b.probe;
    std::vector<glm::dvec3> bevy;
    for (const glm::dvec3& c :
         boxCorners(e.bevy->translation, e.bevy->rotation, e.bevy->scale / 2.0))
      bevy.push_back({c.x, -c.z, c.y});
    EXPECT_LE(cornerDistance(bevy, keptCorners), kTolerance) << b.probe << " bevy";
    for (const EngineSource* source : {&e.unrealBox->source, &e.godot->source, &e.bevy->source}) {
      EXPECT_TRUE(source->keptProxy) << b.probe;
      EXPECT_EQ(source->candidate, candidateName(kept)) << b.probe;
      EXPECT_EQ(source->error.p95Deg, kept.error.p95Deg) << b.probe;
    }
    // Unity: axis-aligned, box centre = position + center, full size grown by the blend
    // distance on every side (what Unity projects on: the kept box, its bottom lowered by the
    // blend distance); left-handed Y up: Unity (u, v, w) is world (-u, -w, v).
    if (methodId(ProxyShape(*box)) == "aabb") {
      ASSERT_TRUE(e.unity) << b.probe;
      // The projected box's bottom lies blend_distance under the kept one's (Unity's y is up).
      const double blend = e.unity->blendDistance;
      std::vector<glm::dvec3> unity;
      for (const glm::dvec3& c : boxCorners(
               e.unity->position + e.unity->center + glm::dvec3(0.0, 0.5 * blend, 0.0),
               glm::dquat(1, 0, 0, 0), e.unity->size / 2.0 + glm::dvec3(blend, 0.5 * blend, blend)))
        unity.push_back({-c.x, -c.z, c.y});
      EXPECT_LE(cornerDistance(unity, keptCorners), kTolerance) << b.probe << " unity";
      EXPECT_TRUE(e.unity->source.keptProxy) << b.probe;
      EXPECT_EQ(e.unity->source.error.p95Deg, kept.error.p95Deg) << b.probe;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Suite, SuiteLevel, ::testing::ValuesIn(kLevels));

}  // namespace
}  // namespace probeproxy
