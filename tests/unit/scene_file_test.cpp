// The scene file: canonical bytes, frame and unit conversion, paths, and one exact message
// per kind of mistake.

#include "geometry/scene/scene_file.h"

#include "core/errors/input_error.h"
#include "tests/unit/test_files.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

namespace fs = std::filesystem;

class SceneFileTest : public testing::TempFolderTest {};

std::string fileBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The example under "### Scene file" in docs/cli_and_formats.md: the documented canonical form.
std::string readmeSceneExample() {
  // This file is tests/unit/scene_file_test.cpp; CMake compiles it by its absolute path.
  const fs::path sourceRoot = fs::path(__FILE__).parent_path().parent_path().parent_path();
  const std::string readme = fileBytes(sourceRoot / "docs" / "cli_and_formats.md");
  const std::size_t section = readme.find("### Scene file");
  const std::string fence = "```json\n";
  const std::size_t start = readme.find(fence, section);
  if (section == std::string::npos || start == std::string::npos) return {};
  const std::size_t end = readme.find("\n```", start + fence.size());
  return readme.substr(start + fence.size(), end + 1 - (start + fence.size()));
}

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << "x";
  EXPECT_NEAR(actual.y, expected.y, tolerance) << "y";
  EXPECT_NEAR(actual.z, expected.z, tolerance) << "z";
}

std::string lineWith(const std::string& text, const std::string& needle) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(needle) != std::string::npos) return line;
  }
  return "(no line with " + needle + ")";
}

// Small scene texts for the checks below: a valid probe, with some fields replaced.
struct Field {
  std::string key;
  std::string json;  // empty: leave the field out
};

std::string probeJson(const std::vector<Field>& changes = {}) {
  std::vector<Field> fields = {
      {"name", R"("a")"},
      {"capture", "[0, 0, 0]"},
      {"influence", R"({"kind": "sphere", "center": [0, 0, 0], "radius": 2})"},
      {"proxy", R"("auto")"}};
  for (const Field& change : changes) {
    auto it = std::find_if(fields.begin(), fields.end(),
                           [&](const Field& field) { return field.key == change.key; });
    if (it == fields.end()) {
      fields.push_back(change);
    } else {
      it->json = change.json;
    }
  }
  std::string text = "{";
  for (const Field& field : fields) {
    if (field.json.empty()) continue;
    text += (text.size() > 1 ? ", \"" : "\"") + field.key + "\": " + field.json;
  }
  return text + "}";
}

constexpr char kHead[] = R"("probeproxy_scene": 1, "up": "Z", "level": ["level.glb"])";

std::string sceneJson(const std::string& probes, const std::string& head = kHead) {
  return "{" + head + ", \"probes\": [" + probes + "]}";
}

// ------------------------------------------------------------------------------------------

TEST_F(SceneFileTest, ReadmeExampleRoundTripsByteExactly) {
  const std::string example = readmeSceneExample();
  ASSERT_FALSE(example.empty())
      << "docs/cli_and_formats.md has no ```json block under ### Scene file";
  const fs::path file = write("level.scene.json", example);

  const Scene scene = readSceneFile(file);
  EXPECT_EQ(sceneFileJson(scene), example);

  writeSceneFile(scene, folder_ / "copy.scene.json");
  EXPECT_EQ(fileBytes(folder_ / "copy.scene.json"), example);
}

TEST_F(SceneFileTest, ReadmeExampleReadsIntoTheWorldFrame) {
  const Scene scene = readSceneFile(write("level.scene.json", readmeSceneExample()));

  EXPECT_EQ(scene.file, folder_ / "level.scene.json");
  EXPECT_EQ(scene.fileUp, UpAxis::Z);
  EXPECT_EQ(scene.metersPerUnit, 1.0);
  ASSERT_EQ(scene.level.size(), 2u);
  EXPECT_EQ(scene.level[0].path, folder_ / "corridor.glb");
  EXPECT_EQ(scene.level[0].pathAsWritten, fs::path("corridor.glb"));
  EXPECT_EQ(scene.level[0].up, UpAxis::Y);  // glTF
  EXPECT_FALSE(scene.level[0].upWasExplicit);
  EXPECT_EQ(scene.level[1].up, UpAxis::Z);
  EXPECT_TRUE(scene.level[1].upWasExplicit);

  ASSERT_EQ(scene.probes.size(), 1u);
  const Probe& probe = scene.probes[0];
  EXPECT_EQ(probe.name, "corridor_a");
  expectNear(probe.captureMeters, {-6.0, 0.0, 1.6});
  const auto* influence = std::get_if<BoxInfluence>(&probe.influence);
  ASSERT_NE(influence, nullptr);
  expectNear(influence->halfExtentsMeters, {3.5, 1.5, 1.5});
  expectNear(influence->innerHalfExtentsMeters, {2.5, 1.5, 1.5});
  EXPECT_EQ(influence->worldFromBox, glm::dquat(1, 0, 0, 0));
  const auto* proxy = std::get_if<AuthoredBox>(&probe.proxy);
  ASSERT_NE(proxy, nullptr);
  expectNear(proxy->halfExtentsMeters, {3.0, 1.5, 1.5});
  ASSERT_TRUE(probe.cubemap.has_value());
  EXPECT_EQ(*probe.cubemap, "cubemaps/corridor_a_{face}.exr");
  ASSERT_EQ(probe.reflectionPlanes.size(), 1u);
  expectNear(probe.reflectionPlanes[0].normal, {0, 0, 1});
}

TEST_F(SceneFileTest, YUpAndZUpFilesReadToTheSameWorldCoordinates) {
  // The same room written twice: Y-up (x, y, z) is Z-up (x, -z, y).
  const std::string yUpProbe =
      probeJson({{"capture", "[1, 2, 3]"},
                 {"influence", R"({"kind": "sphere", "center": [4, 5, 6], "radius": 2})"},
                 {"proxy", R"({"kind": "box", "center": [1, 2, 3], "half_extents": [1, 2, 3]})"},
                 {"reflection_planes", R"([{"point": [0, 1, 0], "normal": [0, 1, 0]}])"}});
  const std::string zUpProbe =
      probeJson({{"capture", "[1, -3, 2]"},
                 {"influence", R"({"kind": "sphere", "center": [4, -6, 5], "radius": 2})"},
                 {"proxy", R"({"kind": "box", "center": [1, -3, 2], "half_extents": [1, 3, 2]})"},
                 {"reflection_planes", R"([{"point": [0, 0, 1], "normal": [0, 0, 1]}])"}});
  const Scene yUp = readSceneFile(
      write("y.scene.json",
            sceneJson(yUpProbe, R"("probeproxy_scene": 1, "up": "Y", "level": ["level.obj"])")));
  const Scene zUp = readSceneFile(write("z.scene.json", sceneJson(zUpProbe)));

  EXPECT_EQ(yUp.fileUp, UpAxis::Y);
  EXPECT_EQ(yUp.level[0].up, UpAxis::Y);  // an OBJ takes the scene's up
  const Probe& a = yUp.probes[0];
  const Probe& b = zUp.probes[0];
  expectNear(a.captureMeters, {1, -3, 2});
  expectNear(b.captureMeters, {1, -3, 2});
  expectNear(std::get<SphereInfluence>(a.influence).centerMeters, {4, -6, 5});
  expectNear(std::get<SphereInfluence>(b.influence).centerMeters, {4, -6, 5});
  // An axis-aligned box stays axis-aligned; its height (file y) becomes world z.
  expectNear(std::get<AuthoredBox>(a.proxy).halfExtentsMeters, {1, 3, 2});
  expectNear(std::get<AuthoredBox>(b.proxy).halfExtentsMeters, {1, 3, 2});
  expectNear(a.reflectionPlanes[0].pointMeters, {0, 0, 1});
  expectNear(a.reflectionPlanes[0].normal, {0, 0, 1});
  expectNear(b.reflectionPlanes[0].normal, {0, 0, 1});
}

TEST_F(SceneFileTest, YUpRotatedBoxHasTheRightWorldCorners) {
  // A Y-up box turned 90 degrees about the file's up axis (Y). By hand: a file corner is
  // center + (3sz, 2sy, -sx) for signs s, i.e. x in {7, 13}, y in {18, 22}, z in {29, 31};
  // the world point (x, -z, y) then has x in {7, 13}, y in {-31, -29}, z in {18, 22}.
  const std::string probe =
      probeJson({{"influence", R"({"kind": "box", "center": [10, 20, 30], "half_extents": [1, 2, 3],
                         "rotation": [0.7071067811865476, 0, 0.7071067811865476, 0]})"}});
  const Scene scene = readSceneFile(
      write("y.scene.json",
            sceneJson(probe, R"("probeproxy_scene": 1, "up": "Y", "level": ["level.obj"])")));
  const auto& box = std::get<BoxInfluence>(scene.probes[0].influence);

  glm::dvec3 lowest(1e9), highest(-1e9);
  bool hasFileCornerPlusPlusPlus = false;  // file (13, 22, 29) is world (13, -29, 22)
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 signs(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    const glm::dvec3 world = box.centerMeters + box.worldFromBox * (signs * box.halfExtentsMeters);
    lowest = glm::min(lowest, world);
    highest = glm::max(highest, world);
    hasFileCornerPlusPlusPlus |= glm::length(world - glm::dvec3(13, -29, 22)) < 1e-9;
  }
  expectNear(lowest, {7, -31, 18}, 1e-9);
  expectNear(highest, {13, -29, 22}, 1e-9);
  EXPECT_TRUE(hasFileCornerPlusPlusPlus);

  // And back: the file keeps its own rotation and half-extents.
  const std::string written = sceneFileJson(scene);
  EXPECT_NE(written.find(R"("half_extents": [1.0, 2.0, 3.0])"), std::string::npos) << written;
  EXPECT_NE(written.find(R"("rotation": [0.707106781, 0.0, 0.707106781, 0.0])"), std::string::npos)
      << written;
}

TEST_F(SceneFileTest, MetersPerUnitScalesLengthsButNotDirections) {
  // 7, 29, 123.45 and 3.3 centimetres are values where x * 0.01 / 0.01 != x in doubles.
  const std::string text = R"({
  "probeproxy_scene": 1,
  "up": "Z",
  "meters_per_unit": 0.01,
  "level": [ { "mesh": "level.obj" } ],
  "probes": [
    {
      "name": "a",
      "capture": [7.0, 29.0, 123.45],
      "influence": { "kind": "sphere", "center": [0.0, 0.0, 0.0], "radius": 50.0,
                     "inner_radius": 3.3 },
      "proxy": { "kind": "box", "center": [0.0, 0.0, 0.0], "half_extents": [10.0, 20.0, 29.0] },
      "reflection_planes": [ { "point": [0.0, 0.0, 7.0], "normal": [0.0, 0.0, 1.0] } ]
    }
  ]
}
)";
  const Scene scene = readSceneFile(write("cm.scene.json", text));
  const Probe& probe = scene.probes[0];
  expectNear(probe.captureMeters, {0.07, 0.29, 1.2345});
  EXPECT_NEAR(std::get<SphereInfluence>(probe.influence).radiusMeters, 0.5, 1e-15);
  EXPECT_NEAR(std::get<SphereInfluence>(probe.influence).innerRadiusMeters, 0.033, 1e-15);
  expectNear(std::get<AuthoredBox>(probe.proxy).halfExtentsMeters, {0.1, 0.2, 0.29});
  expectNear(probe.reflectionPlanes[0].pointMeters, {0, 0, 0.07});
  expectNear(probe.reflectionPlanes[0].normal, {0, 0, 1});  // a direction: not scaled

  EXPECT_EQ(sceneFileJson(scene), text);  // no 7.000000000000001 or 28.999999999999996
}

TEST_F(SceneFileTest, MeasuredWithReadsIntoTheWorldAndWritesBackByteExactly) {
  // A Y-up file in centimetres: seed points turn like captures, lengths scale, the tolerance
  // (degrees) does not.
  const std::string text = R"({
  "probeproxy_scene": 1,
  "up": "Y",
  "meters_per_unit": 0.01,
  "level": [ { "mesh": "level.obj" } ],
  "probes": [],
  "measured_with": {
    "seed_points": [ [100.0, 50.0, -300.0], [7.0, 0.0, 29.0] ],
    "grid": 25.0,
    "step_height": 56.25,
    "head_clearance": 175.0,
    "eye_height": 156.25,
    "tolerance_deg": 5.0
  }
}
)";
  const Scene scene = readSceneFile(write("measured.scene.json", text));
  const MeasureSettings& m = scene.measuredWith;
  ASSERT_EQ(m.seedPointsMeters.size(), 2u);
  expectNear(m.seedPointsMeters[0], {1.0, 3.0, 0.5});  // Y-up (x, y, z) is world (x, -z, y)
  expectNear(m.seedPointsMeters[1], {0.07, -0.29, 0.0});
  EXPECT_NEAR(*m.gridSpacingMeters, 0.25, 1e-15);
  EXPECT_NEAR(*m.stepHeightMeters, 0.5625, 1e-15);
  EXPECT_NEAR(*m.headClearanceMeters, 1.75, 1e-15);
  EXPECT_NEAR(*m.eyeHeightMeters, 1.5625, 1e-15);
  EXPECT_EQ(*m.toleranceDeg, 5.0);
  EXPECT_EQ(sceneFileJson(scene), text);

  // Without it, nothing is said and nothing is written.
  const Scene plain = readSceneFile(write("plain.scene.json", sceneJson("")));
  EXPECT_TRUE(plain.measuredWith.empty());
  EXPECT_EQ(sceneFileJson(plain).find("measured_with"), std::string::npos);
}

TEST_F(SceneFileTest, PlainStringLevelEntriesAreShortForMeshObjects) {
  const Scene scene = readSceneFile(write(
      "s.scene.json",
      sceneJson(probeJson(),
                R"("probeproxy_scene": 1, "up": "Z", "level": ["a.obj", {"mesh": "b.ply"}])")));
  ASSERT_EQ(scene.level.size(), 2u);
  EXPECT_EQ(scene.level[0].path, folder_ / "a.obj");
  EXPECT_EQ(scene.level[0].pathAsWritten, fs::path("a.obj"));
  EXPECT_EQ(scene.level[0].up, UpAxis::Z);
  EXPECT_FALSE(scene.level[0].upWasExplicit);
  EXPECT_EQ(scene.level[1].path, folder_ / "b.ply");
  EXPECT_EQ(lineWith(sceneFileJson(scene), "\"level\""),
            R"(  "level": [ { "mesh": "a.obj" }, { "mesh": "b.ply" } ],)");
}

TEST_F(SceneFileTest, CubemapIsSixFilesOrOneCrossOrEquirectImage) {
  for (const std::string cubemap : {"cubes/a_{face}.exr", "cubes/a_cross.hdr", "a_latlong.png"}) {
    const Scene scene = readSceneFile(
        write("s.scene.json", sceneJson(probeJson({{"cubemap", "\"" + cubemap + "\""}}))));
    ASSERT_TRUE(scene.probes[0].cubemap.has_value());
    EXPECT_EQ(*scene.probes[0].cubemap, cubemap);
    EXPECT_EQ(lineWith(sceneFileJson(scene), "\"cubemap\""),
              "      \"cubemap\": \"" + cubemap + "\"");
  }
}

TEST_F(SceneFileTest, GltfMeshesDefaultToYUpOthersToTheScenes) {
  const Scene zScene = readSceneFile(
      write("z.scene.json", sceneJson(probeJson(), R"("probeproxy_scene": 1, "up": "Z", "level":
                 ["a.glb", "b.GLTF", "c.obj", {"mesh": "d.glb", "up": "Z"}])")));
  EXPECT_EQ(zScene.level[0].up, UpAxis::Y);
  EXPECT_EQ(zScene.level[1].up, UpAxis::Y);  // the extension is case-insensitive
  EXPECT_EQ(zScene.level[2].up, UpAxis::Z);
  EXPECT_EQ(zScene.level[3].up, UpAxis::Z);
  EXPECT_TRUE(zScene.level[3].upWasExplicit);
  EXPECT_EQ(lineWith(sceneFileJson(zScene), "\"level\""),
            R"(  "level": [ { "mesh": "a.glb" }, { "mesh": "b.GLTF" }, { "mesh": "c.obj" },)");
  EXPECT_EQ(lineWith(sceneFileJson(zScene), "d.glb"),
            R"(             { "mesh": "d.glb", "up": "Z" } ],)");

  const Scene yScene = readSceneFile(
      write("y.scene.json",
            sceneJson(probeJson(), R"("probeproxy_scene": 1, "up": "Y", "level": ["e.off"])")));
  EXPECT_EQ(yScene.level[0].up, UpAxis::Y);

  // A Scene built in memory that does not say upWasExplicit still keeps its up axis.
  Scene built = zScene;
  built.level = {LevelMeshRef{folder_ / "f.glb", "f.glb", UpAxis::Z, false, {}}};
  EXPECT_EQ(lineWith(sceneFileJson(built), "\"level\""),
            R"(  "level": [ { "mesh": "f.glb", "up": "Z" } ],)");
}

TEST_F(SceneFileTest, RelativePathsResolveAgainstTheSceneFolder) {
  const std::string probe =
      probeJson({{"proxy", R"({"kind": "convex", "mesh": "proxies/../proxies/a.obj"})"},
                 {"cubemap", R"("cubes/a_{face}.exr")"}});
  const fs::path file = write("levels/a/level.scene.json",
                              sceneJson(probe, R"("probeproxy_scene": 1, "up": "Z", "level":
                 ["../meshes/room.glb", "/opt/shared/props.obj"])"));

  // Read through a relative path: everything still comes out absolute.
  const Scene scene = readSceneFile(fs::proximate(file));
  EXPECT_EQ(scene.file, file);
  EXPECT_EQ(scene.level[0].path, folder_ / "levels/meshes/room.glb");
  EXPECT_EQ(scene.level[0].pathAsWritten, fs::path("../meshes/room.glb"));
  EXPECT_EQ(scene.level[1].path, fs::path("/opt/shared/props.obj"));
  const auto& convex = std::get<AuthoredConvexMesh>(scene.probes[0].proxy);
  EXPECT_EQ(convex.mesh, folder_ / "levels/a/proxies/a.obj");
  EXPECT_EQ(convex.meshAsWritten, fs::path("proxies/../proxies/a.obj"));

  // Written elsewhere, relative paths are respelled for the new folder; absolute ones stay.
  const fs::path copy = folder_ / "other/copy.scene.json";
  writeSceneFile(scene, copy);
  const std::string copyText = fileBytes(copy);
  EXPECT_EQ(
      lineWith(copyText, "\"level\""),
      R"(  "level": [ { "mesh": "../levels/meshes/room.glb" }, { "mesh": "/opt/shared/props.obj" } ],)");
  const Scene reread = readSceneFile(copy);
  EXPECT_EQ(reread.level[0].path, scene.level[0].path);
  EXPECT_EQ(std::get<AuthoredConvexMesh>(reread.probes[0].proxy).mesh, convex.mesh);
  EXPECT_EQ(reread.probes[0].cubemap, "../levels/a/cubes/a_{face}.exr")
      << "the same images, reached from the new folder";
}

TEST_F(SceneFileTest, FailedWriteLeavesNoFileBehind) {
  Scene scene = readSceneFile(write("in.scene.json", sceneJson(probeJson())));
  fs::remove(folder_ / "in.scene.json");
  const fs::path target = folder_ / "out.scene.json";

  Scene duplicate = scene;
  duplicate.probes.push_back(duplicate.probes[0]);
  try {
    writeSceneFile(duplicate, target);
    ADD_FAILURE() << "a duplicate probe name was written";
  } catch (const InputError& error) {
    EXPECT_EQ(error.problem(), R"($.probes[1].name: "a" is used by $.probes[0] already)");
    EXPECT_EQ(error.file(), target);
  }

  Scene notANumber = scene;
  notANumber.probes[0].captureMeters.x = std::nan("");
  try {
    writeSceneFile(notANumber, target);
    ADD_FAILURE() << "a NaN capture point was written";
  } catch (const InputError& error) {
    EXPECT_EQ(error.problem(), "$.probes[0].capture[0]: expected a finite number, got null");
  }
  EXPECT_TRUE(fs::is_empty(folder_));

  // The file system refuses (a folder is in the way): no temporary file is left either.
  fs::create_directory(target);
  EXPECT_THROW(writeSceneFile(scene, target), InputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
  EXPECT_TRUE(fs::is_empty(target));
}

TEST_F(SceneFileTest, WrittenFilesAreAFixedPoint) {
  // Arbitrary rotations, normals and positions in a Y-up, inch-based file: the conversions
  // and normalizations on read must not change what is written next time. Fixed seed.
  std::mt19937 random(20240611);
  std::uniform_real_distribution<double> coordinate(-500.0, 500.0);
  std::uniform_real_distribution<double> size(0.01, 20.0);
  std::normal_distribution<double> gaussian;
  const auto randomRotation = [&] {
    return glm::normalize(
        glm::dquat(gaussian(random), gaussian(random), gaussian(random), gaussian(random)));
  };
  const auto randomPoint = [&] {
    return glm::dvec3(coordinate(random), coordinate(random), coordinate(random));
  };
  const auto randomSize = [&] { return glm::dvec3(size(random), size(random), size(random)); };

  Scene scene;
  scene.fileUp = UpAxis::Y;
  scene.metersPerUnit = 0.0254;
  scene.level = {LevelMeshRef{folder_ / "level.glb", "level.glb", UpAxis::Y, false, {}}};
  for (int i = 0; i < 60; ++i) {
    Probe probe;
    probe.name = "probe_" + std::to_string(i);
    probe.captureMeters = randomPoint();
    const glm::dvec3 outer = randomSize();
    if (i % 2 == 0) {
      probe.influence = BoxInfluence{randomPoint(), outer, randomRotation(), outer * 0.5};
    } else {
      probe.influence = SphereInfluence{randomPoint(), outer.x, outer.x * 0.75};
    }
    switch (i % 7) {
      case 0:
        probe.proxy = AutoProxy{};
        break;
      case 1:
        probe.proxy = InfiniteProxy{};
        break;
      case 2:
        probe.proxy = AuthoredBox{randomPoint(), randomSize()};
        break;
      case 3:
        probe.proxy = AuthoredObb{randomPoint(), randomSize(), randomRotation()};
        break;
      case 4:
        probe.proxy = AuthoredSphere{randomPoint(), size(random)};
        break;
      case 5:
        probe.proxy = AuthoredCheapK{1.0 / size(random)};
        break;
      default:
        probe.proxy = AuthoredConvexMesh{folder_ / "hull.ply", "hull.ply"};
        break;
    }
    probe.reflectionPlanes = {ReflectionPlane{
        randomPoint(),
        glm::normalize(glm::dvec3(gaussian(random), gaussian(random), gaussian(random)))}};
    scene.probes.push_back(probe);
  }

  const fs::path file = folder_ / "random.scene.json";
  writeSceneFile(scene, file);
  const std::string first = fileBytes(file);
  const Scene reread = readSceneFile(file);
  EXPECT_EQ(sceneFileJson(reread), first);
  writeSceneFile(reread, file);
  EXPECT_EQ(fileBytes(file), first);

  // And what was read is what was written, to the written precision (1e-9 inch).
  for (std::size_t i = 0; i < scene.probes.size(); ++i) {
    SCOPED_TRACE(scene.probes[i].name);
    expectNear(reread.probes[i].captureMeters, scene.probes[i].captureMeters, 1e-10);
    if (const auto* box = std::get_if<BoxInfluence>(&scene.probes[i].influence)) {
      const auto& readBox = std::get<BoxInfluence>(reread.probes[i].influence);
      expectNear(readBox.halfExtentsMeters, box->halfExtentsMeters, 1e-10);
      EXPECT_NEAR(glm::dot(readBox.worldFromBox, box->worldFromBox), 1.0, 1e-8);
    }
    expectNear(reread.probes[i].reflectionPlanes[0].normal,
               scene.probes[i].reflectionPlanes[0].normal, 1e-8);
  }
}

// k is per file unit: the lookup k * (x - C) is the same whatever unit x is written in.
TEST_F(SceneFileTest, CheapKIsPerFileUnit) {
  const std::string scene =
      sceneJson(probeJson({{"proxy", R"({"kind": "cheap_k", "k": 0.0025})"}}),
                R"("probeproxy_scene": 1, "up": "Z", "meters_per_unit": 0.01, "level": ["a.obj"])");
  const Scene read = readSceneFile(write("cm.scene.json", scene));
  EXPECT_NEAR(std::get<AuthoredCheapK>(read.probes[0].proxy).kPerMeter, 0.25, 1e-15);
  EXPECT_EQ(lineWith(sceneFileJson(read), "\"proxy\""),
            R"(      "proxy": { "kind": "cheap_k", "k": 0.0025 })");
}

TEST_F(SceneFileTest, ConversionNoiseNeverShows) {
  Scene scene = readSceneFile(write("in.scene.json", sceneJson(probeJson())));
  scene.probes[0].captureMeters = {0.1 + 0.2, -0.0, 1e-17};
  EXPECT_EQ(lineWith(sceneFileJson(scene), "capture"), R"(      "capture": [0.3, 0.0, 0.0],)");

  // A quarter turn about world X, written Y-up: conjugation leaves ~1e-16 residue.
  scene.fileUp = UpAxis::Y;
  scene.probes[0].influence = BoxInfluence{
      {0, 0, 0}, {1, 1, 1}, glm::angleAxis(glm::half_pi<double>(), glm::dvec3(1, 0, 0)), {1, 1, 1}};
  EXPECT_NE(sceneFileJson(scene).find(R"("rotation": [0.707106781, 0.707106781, 0.0, 0.0])"),
            std::string::npos)
      << sceneFileJson(scene);
}

TEST_F(SceneFileTest, QuaternionsAndNormalsAreNormalized) {
  const std::string probe =
      probeJson({{"influence", R"({"kind": "box", "center": [0, 0, 0], "half_extents": [1, 1, 1],
                         "rotation": [0.9995, 0, 0, 0]})"},
                 {"reflection_planes", R"([{"point": [0, 0, 0], "normal": [0, 0, 3e200]}])"}});
  const Scene scene = readSceneFile(write("n.scene.json", sceneJson(probe)));
  const auto& box = std::get<BoxInfluence>(scene.probes[0].influence);
  EXPECT_DOUBLE_EQ(box.worldFromBox.w, 1.0);
  expectNear(scene.probes[0].reflectionPlanes[0].normal, {0, 0, 1});
}

// ------------------------------------------------------------------------------------------
// One line per mistake, exactly.

struct ErrorCase {
  std::string name;
  std::string text;     // the file's bytes; see kNoFile and kFolder
  std::string problem;  // InputError::problem(), exactly
};

// GoogleTest names a failing case by this rather than by its bytes.
void PrintTo(const ErrorCase& mistake, std::ostream* out) { *out << mistake.name; }

const std::string kNoFile = "(no file)";
const std::string kFolder = "(a folder)";

std::vector<ErrorCase> errorCases() {
  const std::string box = R"({"kind": "box", "center": [0, 0, 0], "half_extents": [3.5, 1.5, 1.5])";
  return {
      {"missing_file", kNoFile, "cannot open: No such file or directory"},
      {"folder", kFolder, "JSON file is a folder, not a regular file"},
      {"invalid_json", "{\n  \"probeproxy_scene\": 1,\n  \"up\": }\n",
       "invalid JSON at line 3, column 9: syntax error while parsing value - unexpected '}'; "
       "expected '[', '{', or a literal"},
      {"invalid_json_column_counts_characters", "{\"up\": \"\xC3\xA9\xC3\xA9\" \"x\"}",
       "invalid JSON at line 1, column 15: syntax error while parsing object - unexpected "
       "string literal; expected '}'"},
      {"number_too_large", sceneJson(probeJson({{"capture", "[0, 1e400, 0]"}})),
       "$.probes[0].capture[1]: expected a finite number, got 1e400"},
      {"duplicate_member", sceneJson(R"({"name": "a", "name": "b"})"),
       "$.probes[0].name: duplicate member"},
      {"not_an_object", "[1, 2]", "$: expected an object, got [1, 2]"},
      {"missing_version", R"({"up": "Z"})", R"($: expected member "probeproxy_scene")"},
      {"wrong_version", R"({"probeproxy_scene": 2})", "$.probeproxy_scene: expected 1, got 2"},
      {"missing_up", R"({"probeproxy_scene": 1, "level": ["a.obj"], "probes": []})",
       R"($: expected member "up")"},
      {"wrong_up", sceneJson("", R"("probeproxy_scene": 1, "up": "X", "level": ["a.obj"])"),
       R"($.up: expected "Y" or "Z", got "X")"},
      {"zero_meters_per_unit",
       sceneJson("", R"("probeproxy_scene": 1, "up": "Z", "meters_per_unit": 0, "level": [])"),
       "$.meters_per_unit: expected a positive number, got 0"},
      {"missing_probes", R"({"probeproxy_scene": 1, "up": "Z", "level": ["a.obj"]})",
       R"($: expected member "probes")"},
      {"unknown_member_typo", sceneJson("", std::string(kHead) + R"(, "levels": [])"),
       R"($.levels: unknown member (did you mean "level"?))"},
      {"unknown_member", sceneJson(probeJson({{"colour", R"("red")"}})),
       R"($.probes[0].colour: unknown member (expected one of "name", "capture", "influence", )"
       R"("proxy", "cubemap", "reflection_planes"))"},
      {"measured_with_negative_step",
       sceneJson("", std::string(kHead) + R"(, "measured_with": {"step_height": -1})"),
       "$.measured_with.step_height: expected a positive number, got -1"},
      {"measured_with_seed_outside_the_scene",
       sceneJson("", std::string(kHead) + R"(, "measured_with": {"seed_points": [[0, 0, 1e9]]})"),
       "$.measured_with.seed_points[0]: expected coordinates within 100000 m (the limit of a "
       "scene, in metres), got [0, 0, 1000000000.0]"},
      {"measured_with_unknown_member",
       sceneJson("", std::string(kHead) + R"(, "measured_with": {"step": 1})"),
       R"($.measured_with.step: unknown member (expected one of "seed_points", "grid", )"
       R"("step_height", "head_clearance", "eye_height", "tolerance_deg"))"},
      {"unknown_member_odd_key", sceneJson("", std::string(kHead) + R"(, "my key": 1)"),
       R"($["my key"]: unknown member (expected one of "probeproxy_scene", "up", )"
       R"("meters_per_unit", "level", "probes", "measured_with"))"},
      {"empty_level", sceneJson("", R"("probeproxy_scene": 1, "up": "Z", "level": [])"),
       "$.level: expected a non-empty array of meshes, got []"},
      {"mesh_extension", sceneJson("", R"("probeproxy_scene": 1, "up": "Z", "level": ["a.fbx"])"),
       R"($.level[0]: expected a mesh path ending in .glb, .gltf, .obj, .ply, .off, .bsp or )"
       R"(.pk3, got "a.fbx")"},
      {"level_entry_type", sceneJson("", R"("probeproxy_scene": 1, "up": "Z", "level": [3])"),
       R"($.level[0]: expected a mesh path or an object with "mesh", got 3)"},
      {"level_up",
       sceneJson("",
                 R"("probeproxy_scene": 1, "up": "Z", "level": [{"mesh": "a.obj", "up": "y"}])"),
       R"($.level[0].up: expected "Y" or "Z", got "y")"},
      {"probes_not_array",
       R"({"probeproxy_scene": 1, "up": "Z", "level": ["a.obj"], "probes": {}})",
       "$.probes: expected an array of probes, got {}"},
      {"capture_not_numbers", sceneJson(probeJson({{"capture", R"("abc")"}})),
       R"($.probes[0].capture: expected an array of 3 finite numbers, got "abc")"},
      {"capture_two_numbers", sceneJson(probeJson({{"capture", "[1, 2]"}})),
       "$.probes[0].capture: expected an array of 3 finite numbers, got [1, 2]"},
      {"capture_element_names_itself", sceneJson(probeJson({{"capture", R"([0, "x", 1])"}})),
       R"($.probes[0].capture[1]: expected a finite number, got "x")"},
      {"capture_missing", sceneJson(probeJson({{"capture", ""}})),
       R"($.probes[0]: expected member "capture")"},
      {"capture_misspelled", sceneJson(probeJson({{"capture", ""}, {"captur", "[0, 0, 0]"}})),
       R"($.probes[0].captur: unknown member (did you mean "capture"?))"},
      {"long_value_is_cut", sceneJson(probeJson({{"capture", '"' + std::string(100, 'x') + '"'}})),
       "$.probes[0].capture: expected an array of 3 finite numbers, got \"" + std::string(56, 'x') +
           "..."},
      {"empty_name", sceneJson(probeJson({{"name", R"("")"}})),
       R"($.probes[0].name: expected a non-empty string, got "")"},
      {"duplicate_name",
       sceneJson(probeJson({{"name", R"("hall_a")"}}) + ", " +
                 probeJson({{"name", R"("hall_b")"}}) + ", " +
                 probeJson({{"name", R"("hall_a")"}})),
       R"($.probes[2].name: "hall_a" is used by $.probes[0] already)"},
      {"negative_radius",
       sceneJson(
           probeJson() + ", " +
           probeJson({{"name", R"("b")"},
                      {"influence", R"({"kind": "sphere", "center": [0, 0, 0], "radius": -2})"}})),
       "$.probes[1].influence.radius: expected a positive number, got -2"},
      {"influence_kind", sceneJson(probeJson({{"influence", R"({"kind": "cube"})"}})),
       R"($.probes[0].influence.kind: expected "box" or "sphere", got "cube")"},
      {"sphere_member_on_box", sceneJson(probeJson({{"influence", box + R"(, "radius": 1})"}})),
       R"($.probes[0].influence.radius: unknown member (expected one of "kind", "center", )"
       R"("half_extents", "rotation", "inner_half_extents"))"},
      {"zero_half_extent",
       sceneJson(probeJson(
           {{"influence", R"({"kind": "box", "center": [0, 0, 0], "half_extents": [1, 0, 1]})"}})),
       "$.probes[0].influence.half_extents[1]: expected a positive number, got 0"},
      {"inner_past_outer",
       sceneJson(probeJson({{"influence", box + R"(, "inner_half_extents": [4, 1, 1]})"}})),
       "$.probes[0].influence.inner_half_extents: expected an array of 3 positive numbers, each "
       "at most half_extents [3.5, 1.5, 1.5], got [4, 1, 1]"},
      {"inner_radius_past_radius",
       sceneJson(probeJson(
           {{"influence",
             R"({"kind": "sphere", "center": [0, 0, 0], "radius": 2, "inner_radius": 3})"}})),
       "$.probes[0].influence.inner_radius: expected a positive number at most radius 2, got 3"},
      {"rotation_not_unit",
       sceneJson(probeJson({{"influence", box + R"(, "rotation": [2, 0, 0, 0]})"}})),
       "$.probes[0].influence.rotation: expected a unit quaternion [w, x, y, z] (length within "
       "1e-3 of 1), got [2, 0, 0, 0]"},
      {"proxy_misspelled", sceneJson(probeJson({{"proxy", R"("aut")"}})),
       R"($.probes[0].proxy: expected "auto", "infinite" or an object, got "aut")"},
      {"proxy_kind", sceneJson(probeJson({{"proxy", R"({"kind": "aabb"})"}})),
       R"($.probes[0].proxy.kind: expected "box", "obb", "sphere", "cheap_k" or "convex", got )"
       R"("aabb")"},
      {"cheap_k_negative", sceneJson(probeJson({{"proxy", R"({"kind": "cheap_k", "k": -0.5})"}})),
       "$.probes[0].proxy.k: expected a number >= 0, got -0.5"},
      {"obb_without_rotation",
       sceneJson(probeJson(
           {{"proxy", R"({"kind": "obb", "center": [0, 0, 0], "half_extents": [1, 1, 1]})"}})),
       R"($.probes[0].proxy: expected member "rotation")"},
      {"convex_mesh_extension",
       sceneJson(probeJson({{"proxy", R"({"kind": "convex", "mesh": "hull.stl"})"}})),
       R"($.probes[0].proxy.mesh: expected a mesh path ending in .glb, .gltf, .obj, .ply or )"
       R"(.off, got "hull.stl")"},
      {"cubemap_not_an_image", sceneJson(probeJson({{"cubemap", R"("probe_{face}.txt")"}})),
       R"($.probes[0].cubemap: expected an .exr, .hdr or .png image path (six files with )"
       R"({face}, or one cross or equirectangular image), got "probe_{face}.txt")"},
      {"overflow_in_metres",
       sceneJson(probeJson({{"capture", "[1e303, 0, 0]"}}),
                 R"("probeproxy_scene": 1, "up": "Z", "meters_per_unit": 1e6, "level": ["a.obj"])"),
       "$.probes[0].capture: expected numbers that stay finite in metres, got [1e+303, 0, 0]"},
      // Numbers a level cannot hold are refused when the scene is read, so nothing
      // past the reader meets them (Embree's assertion, the weight grid, an allocation).
      {"half_extents_past_the_scene_limit",
       sceneJson(probeJson(
           {{"influence",
             R"({"kind": "box", "center": [0, 0, 0], "half_extents": [1e308, 1.5, 1.5]})"}})),
       "$.probes[0].influence.half_extents: expected half-extents within 100000 m (the limit of "
       "a scene, in metres), got [1e+308, 1.5, 1.5]"},
      {"center_past_the_scene_limit",
       sceneJson(probeJson(
           {{"influence", R"({"kind": "sphere", "center": [1.2e29, 0, 1.5], "radius": 2})"}})),
       "$.probes[0].influence.center: expected coordinates within 100000 m (the limit of a "
       "scene, in metres), got [1.2e+29, 0, 1.5]"},
      {"meters_per_unit_past_its_range",
       sceneJson(
           probeJson(),
           R"("probeproxy_scene": 1, "up": "Z", "meters_per_unit": 1e300, "level": ["a.obj"])"),
       "$.meters_per_unit: expected a number from 1e-06 to 1e+06, got 1e+300"},
      {"radius_past_the_scene_limit",
       sceneJson(
           probeJson({{"influence", R"({"kind": "sphere", "center": [0, 0, 0], "radius": 3e5})"}})),
       "$.probes[0].influence.radius: expected a length within 100000 m (the limit of a scene, "
       "in metres), got 300000.0"},
      {"level_nested_deeper_than_the_json_limit",
       "{\"probeproxy_scene\": 1, \"level\": " + std::string(100000, '[') +
           std::string(100000, ']') + "}",
       "$.level" +
           [] {
             std::string indices;
             for (int depth = 1; depth < 64; ++depth) indices += "[0]";
             return indices;
           }() +
           ": nested deeper than 64 arrays and objects (the limit of probeproxy's JSON files)"},
      {"zero_normal",
       sceneJson(
           probeJson({{"reflection_planes", R"([{"point": [0, 0, 0], "normal": [0, 0, 0]}])"}})),
       "$.probes[0].reflection_planes[0].normal: expected a non-zero direction (an array of 3 "
       "finite numbers), got [0, 0, 0]"},
  };
}

class SceneFileErrorTest : public testing::TempFolderTest,
                           public ::testing::WithParamInterface<ErrorCase> {};

TEST_P(SceneFileErrorTest, NamesTheFileThePathAndTheProblem) {
  const ErrorCase& mistake = GetParam();
  const fs::path file = folder_ / "case.scene.json";
  if (mistake.text == kFolder) {
    fs::create_directory(file);
  } else if (mistake.text != kNoFile) {
    write("case.scene.json", mistake.text);
  }
  try {
    readSceneFile(file);
    ADD_FAILURE() << "read without an error:\n" << mistake.text;
  } catch (const InputError& error) {
    EXPECT_EQ(error.problem(), mistake.problem) << mistake.text;
    EXPECT_EQ(error.file(), file);
    // The one line a front end prints names the file and holds the problem.
    const std::string line = error.what();
    EXPECT_NE(line.find("case.scene.json"), std::string::npos) << line;
    EXPECT_NE(line.find(mistake.problem), std::string::npos) << line;
  }
}

INSTANTIATE_TEST_SUITE_P(SceneFile, SceneFileErrorTest, ::testing::ValuesIn(errorCases()),
                         [](const ::testing::TestParamInfo<ErrorCase>& param) {
                           return param.param.name;
                         });

}  // namespace
}  // namespace probeproxy
