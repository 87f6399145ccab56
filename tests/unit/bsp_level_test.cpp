// The Quake 3 BSP loader on small files written here (synthetic_bsp.h): no game data needed.
#include "geometry/level/bsp/bsp_level.h"
#include "core/errors/input_error.h"
#include "geometry/level/bsp/bezier_patch.h"
#include "geometry/level/bsp/bsp_surface_flags.h"
#include "geometry/level/load_level.h"
#include "geometry/raycast/floor_below.h"
#include "geometry/scene/scene_file.h"
#include "synthetic_bsp.h"
#include "test_files.h"

#include <gtest/gtest.h>
#include <zip.h>
#include <glm/geometric.hpp>

#include <map>
#include <utility>

namespace probeproxy {
namespace {

using testing::boxRoomBsp;
using testing::SyntheticBsp;
using testing::SyntheticFace;

std::vector<std::byte> asBytes(const std::string& text) {
  std::vector<std::byte> bytes(text.size());
  std::memcpy(bytes.data(), text.data(), text.size());
  return bytes;
}

std::string loadError(const std::string& bytes, const std::string& name = "test.bsp") {
  try {
    parseBspLevel(asBytes(bytes), name);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

glm::vec3 triangleNormal(const LevelMesh& mesh, const glm::uvec3& t) {
  const glm::vec3 a = mesh.positionsMeters[t.x], b = mesh.positionsMeters[t.y],
                  c = mesh.positionsMeters[t.z];
  return glm::cross(b - a, c - a);
}

class BspLevelTest : public testing::TempFolderTest {};

TEST(BspLevel, BoxRoomLoadsToItsSixWallsFacingInwardsInMetres) {
  const SyntheticBsp bsp = boxRoomBsp({256, 128, 96});  // 8 x 4 x 3 m
  const BspLevel level = parseBspLevel(asBytes(bsp.bytes()), "box.bsp");

  EXPECT_EQ(level.faces.polygons, 6u);
  ASSERT_EQ(level.mesh.triangles.size(), 12u);
  ASSERT_EQ(level.mesh.parts.size(), 1u);
  EXPECT_EQ(level.mesh.parts[0].name, "textures/test/wall");
  EXPECT_EQ(level.mesh.parts[0].triangleCount, 12u);
  EXPECT_TRUE(level.mesh.skyTriangles.empty());

  const LevelMeshStats stats = measureLevelMesh(level.mesh);
  EXPECT_EQ(stats.boundsMinMeters, glm::vec3(0.0f));
  EXPECT_EQ(stats.boundsMaxMeters, glm::vec3(8.0f, 4.0f, 3.0f));

  // Each wall: two triangles with the same axis normal, pointing into the room.
  const glm::vec3 centre(4.0f, 2.0f, 1.5f);
  std::map<std::pair<int, int>, int> trianglesPerWall;  // (axis, sign) -> count
  for (const glm::uvec3& t : level.mesh.triangles) {
    const glm::vec3 n = glm::normalize(triangleNormal(level.mesh, t));
    const glm::vec3 p = level.mesh.positionsMeters[t.x];
    EXPECT_GT(glm::dot(n, centre - p), 0.0f) << "triangle faces out of the room";
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
    }
    EXPECT_FLOAT_EQ(std::abs(n[axis]), 1.0f);
    ++trianglesPerWall[{axis, n[axis] > 0 ? 1 : -1}];
  }
  ASSERT_EQ(trianglesPerWall.size(), 6u);
  for (const auto& [wall, count] : trianglesPerWall) EXPECT_EQ(count, 2);
}

// A 5 x 3 control grid: two biquadratic pieces side by side, bent into an arch.
std::vector<glm::vec3> archControlPoints() {
  std::vector<glm::vec3> control;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const float z = (x % 2 == 1) ? 64.0f : (x == 2 ? 48.0f : 0.0f);
      control.emplace_back(32.0f * x, 32.0f * y, z);
    }
  }
  return control;
}

TEST(BspLevel, ItsFloorIsWalkedByQuake3sPlayer) {
  const SyntheticBsp bsp = boxRoomBsp({256, 128, 96});
  const LevelMesh mesh = parseBspLevel(asBytes(bsp.bytes()), "box.bsp").mesh;
  // STEPSIZE 18, playerMins/playerMaxs z -24..32, DEFAULT_VIEWHEIGHT 26 over the origin.
  EXPECT_EQ(*mesh.gamePlayer.stepHeightMeters, 18.0 / 32.0);
  EXPECT_EQ(*mesh.gamePlayer.headClearanceMeters, 56.0 / 32.0);
  EXPECT_EQ(*mesh.gamePlayer.eyeHeightMeters, 50.0 / 32.0);
  EXPECT_FALSE(mesh.gamePlayer.gridSpacingMeters) << "the grid is the survey's, not the game's";
  EXPECT_TRUE(mesh.facesOneSided) << "a BSP keeps each face toward the playable space";
}

TEST(BspLevel, PatchIsWatertightWithinItsOwnGrid) {
  std::vector<glm::dvec3> control;
  for (const glm::vec3& p : archControlPoints()) control.emplace_back(p);
  const int s = 4;
  const TessellatedPatch patch = tessellateBezierPatch(control, 5, 3, s);
  const int columns = 2 * s + 1, rows = s + 1;
  ASSERT_EQ(patch.points.size(), std::size_t(columns * rows));
  ASSERT_EQ(patch.triangles.size(), std::size_t((columns - 1) * (rows - 1) * 2));

  // Every edge is shared by exactly two triangles, except the grid's outer border, used once.
  std::map<std::pair<unsigned, unsigned>, int> uses;
  for (const glm::uvec3& t : patch.triangles) {
    for (int k = 0; k < 3; ++k) {
      const unsigned a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  int border = 0;
  for (const auto& [edge, count] : uses) {
    ASSERT_LE(count, 2);
    if (count == 1) ++border;
  }
  EXPECT_EQ(border, 2 * (columns - 1) + 2 * (rows - 1));

  // A Bezier patch passes through its corner control points, and through the pieces' shared
  // border row exactly (the control point there, x = 64, lies on both pieces).
  EXPECT_EQ(patch.points.front(), control.front());
  EXPECT_EQ(patch.points[columns - 1], control[4]);
  EXPECT_EQ(patch.points[s], control[2]);
  // It stays inside its control points' bounds.
  for (const glm::dvec3& p : patch.points) {
    EXPECT_GE(p.z, 0.0);
    EXPECT_LE(p.z, 64.0);
  }
}

TEST(BspLevel, PatchSubdivisionIsAnOption) {
  SyntheticBsp bsp = boxRoomBsp({256, 128, 96});
  bsp.addPatch(0, 5, 3, archControlPoints());
  for (const int s : {1, 4, 8}) {
    BspLoadOptions options;
    options.patchSubdivisions = s;
    const BspLevel level = parseBspLevel(asBytes(bsp.bytes()), "patch.bsp", options);
    EXPECT_EQ(level.faces.patches, 1u);
    EXPECT_EQ(level.mesh.triangles.size(), 12u + std::size_t(2 * s * s * 2)) << s;
    // The arch's triangles face up (+z side), as the control grid's order says.
    for (std::size_t i = 12; i < level.mesh.triangles.size(); ++i) {
      EXPECT_GE(triangleNormal(level.mesh, level.mesh.triangles[i]).z, 0.0f);
    }
  }
}

TEST(BspLevel, SkyIsRecordedAndNonSolidFacesAreSkippedByTheirFlags) {
  SyntheticBsp bsp = boxRoomBsp({256, 128, 96});
  // Names say nothing: only the flags decide.
  bsp.shaders.push_back({"a", kSurfSky | 0x10 /* noimpact */, 0});
  bsp.shaders.push_back({"b", kSurfNoDraw, kContentsPlayerClip});
  bsp.shaders.push_back({"c", 0, kContentsWater});
  bsp.shaders.push_back({"d", 0, kContentsTrigger});
  bsp.shaders.push_back({"e", kSurfHint, 0});
  bsp.addPolygon(1, {{0, 0, 90}, {256, 0, 90}, {256, 128, 90}, {0, 128, 90}});  // sky
  for (int shader = 2; shader <= 5; ++shader) {
    bsp.addPolygon(shader, {{0, 0, 10}, {256, 0, 10}, {256, 128, 10}});
  }
  SyntheticFace flare;
  flare.shader = 999;  // a flare's shader is never looked at
  flare.type = 4;
  bsp.faces.push_back(flare);

  const BspLevel level = parseBspLevel(asBytes(bsp.bytes()), "sky.bsp");
  EXPECT_EQ(level.mesh.triangles.size(), 12u);
  EXPECT_EQ(level.mesh.skyTriangles.size(), 2u);
  EXPECT_EQ(level.faces.sky, 1u);
  EXPECT_EQ(level.faces.skippedByFlags, 4u);
  EXPECT_EQ(level.faces.billboards, 1u);
  ASSERT_EQ(level.mesh.parts.size(), 1u);  // sky triangles are in no part
  for (const glm::uvec3& t : level.mesh.skyTriangles) {
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(level.mesh.positionsMeters[t[k]].z, 90.0f / 32);
  }

  // Appended after another mesh (a scene's second level entry), sky indices move with it.
  LevelMesh both = parseBspLevel(asBytes(boxRoomBsp({64, 64, 64}).bytes()), "first.bsp").mesh;
  appendLevelMesh(both, level.mesh);
  ASSERT_EQ(both.skyTriangles.size(), 2u);
  EXPECT_EQ(measureLevelMesh(both).skyTriangles, 2u);
  for (const glm::uvec3& t : both.skyTriangles) {
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(both.positionsMeters[t[k]].z, 90.0f / 32);
  }
}

TEST(BspLevel, ATruncatedLumpIsOneLineNamingIt) {
  const SyntheticBsp bsp = boxRoomBsp({256, 128, 96});
  std::string bytes = bsp.bytes();
  const SyntheticBsp::Layout l = bsp.layout();
  bytes.resize(bytes.size() - 10);  // the surfaces lump is the last one with data
  const std::string expected =
      "room.bsp: lump 13 (surfaces): runs past the end of the file "
      "(offset " +
      std::to_string(l.offset[13]) + " + length " + std::to_string(l.length[13]) + " > " +
      std::to_string(bytes.size()) + " bytes)";
  EXPECT_EQ(loadError(bytes, "room.bsp"), expected);
}

TEST(BspLevel, BadIndexesAndRecordsNameTheLump) {
  SyntheticBsp bsp = boxRoomBsp({256, 128, 96});
  bsp.faces[2].numVerts = 400;
  EXPECT_EQ(loadError(bsp.bytes()),
            "test.bsp: lump 13 (surfaces): face 2 uses vertices 8..408 of 24 in lump 10 "
            "(drawverts)");

  bsp = boxRoomBsp({256, 128, 96});
  bsp.indexes[7] = 9;
  EXPECT_EQ(loadError(bsp.bytes()),
            "test.bsp: lump 13 (surfaces): face 1 index 7 is 9, past its 4 vertices");

  bsp = boxRoomBsp({256, 128, 96});
  bsp.faces[0].shader = 3;
  EXPECT_EQ(loadError(bsp.bytes()),
            "test.bsp: lump 13 (surfaces): face 0 uses shader 3 of 1 in lump 1 (shaders)");

  bsp = boxRoomBsp({256, 128, 96});
  bsp.addPatch(0, 4, 3, std::vector<glm::vec3>(12));
  EXPECT_EQ(loadError(bsp.bytes()),
            "test.bsp: lump 13 (surfaces): face 6 is a 4 x 3 patch with 12 control points "
            "(expected odd sizes of at least 3, width x height points)");

  std::string bytes = boxRoomBsp({256, 128, 96}).bytes();
  bytes[12 + 8 * 1] = 71;  // shaders lump length 71: not whole 72-byte records
  EXPECT_EQ(loadError(bytes),
            "test.bsp: lump 1 (shaders): length 71 is not a whole number of 72-byte records");

  EXPECT_EQ(loadError("IBSP"),
            "test.bsp: not a Quake 3 BSP: 4 bytes, shorter than the 144-byte header");
  bytes = boxRoomBsp({256, 128, 96}).bytes();
  bytes[4] = 47;
  EXPECT_EQ(loadError(bytes), "test.bsp: unsupported BSP version 47 (expected 46, Quake III)");
}

TEST(BspLevel, EntityLumpGivesSpawnPointsAndLights) {
  SyntheticBsp bsp = boxRoomBsp({256, 128, 96});
  bsp.entities =
      "{\n\"classname\" \"worldspawn\"\n\"message\" \"test { room }\"\n}\n"
      "{\n\"classname\" \"info_player_deathmatch\"\n\"origin\" \"32 64 24\"\n\"angle\" \"90\"\n}\n"
      "{\n\"origin\" \"-32 0 8\"\n\"classname\" \"info_player_team2\"\n"
      "\"angles\" \"10 180 0\"\n}\n"
      "{\n\"classname\" \"team_CTF_redspawn\"\n\"origin\" \"0 0 0\"\n}\n"
      "{\n\"classname\" \"info_player_intermission\"\n\"origin\" \"0 0 0\"\n}\n"
      "{\n\"classname\" \"light\"\n\"origin\" \"16 16 80\"\n\"light\" \"450\"\n"
      "\"_color\" \"1 0.5 0.25\"\n}\n";
  const BspLevel level = parseBspLevel(asBytes(bsp.bytes()), "ents.bsp");
  EXPECT_EQ(level.entities.size(), 6u);
  EXPECT_EQ(level.entities[0].value("message"), "test { room }");
  ASSERT_EQ(level.spawnPoints.size(), 3u);
  EXPECT_EQ(level.spawnPoints[0].classname, "info_player_deathmatch");
  EXPECT_EQ(level.spawnPoints[0].originMeters, glm::dvec3(1.0, 2.0, 0.75));
  EXPECT_EQ(level.spawnPoints[0].anglesDegrees, glm::dvec3(0.0, 90.0, 0.0));
  EXPECT_EQ(level.spawnPoints[1].classname, "info_player_team2");
  EXPECT_EQ(level.spawnPoints[1].originMeters, glm::dvec3(-1.0, 0.0, 0.25));
  EXPECT_EQ(level.spawnPoints[1].anglesDegrees, glm::dvec3(10.0, 180.0, 0.0));
  EXPECT_EQ(level.spawnPoints[2].classname, "team_CTF_redspawn");
  // The floor under each spawn point: the room's floor at z = 0, 0.75 m (24 units) below the
  // first one's origin; nothing under a point outside the room.
  const LevelRayCaster caster(level.mesh);
  EXPECT_EQ(floorHeightBelow(caster, level.spawnPoints[0].originMeters, 64.0f), 0.0);
  EXPECT_EQ(floorHeightBelow(caster, level.spawnPoints[1].originMeters, 64.0f), std::nullopt);
  ASSERT_EQ(level.lights.size(), 1u);
  EXPECT_EQ(level.lights[0].originMeters, glm::dvec3(0.5, 0.5, 2.5));
  EXPECT_EQ(level.lights[0].intensity, 450.0);
  EXPECT_EQ(level.lights[0].color, glm::dvec3(1.0, 0.5, 0.25));

  bsp.entities = "{\n\"classname\" \"info_player_start\"\n\"origin\" \"1 2\"\n}\n";
  EXPECT_EQ(loadError(bsp.bytes()),
            "test.bsp: lump 0 (entities): entity 0 (info_player_start) origin \"1 2\" is not "
            "three numbers");
  bsp.entities = "{\n\"classname\" \"worldspawn\n}\n";
  EXPECT_EQ(loadError(bsp.bytes()), "test.bsp: lump 0 (entities): unclosed quote at byte 14");
}

void writeZip(const std::filesystem::path& archive, const std::string& entry,
              const std::string& bytes) {
  int error = 0;
  zip_t* zip = zip_open(archive.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(zip, nullptr);
  zip_source_t* source = zip_source_buffer(zip, bytes.data(), bytes.size(), 0);
  ASSERT_GE(zip_file_add(zip, entry.c_str(), source, ZIP_FL_ENC_UTF_8), 0);
  ASSERT_EQ(zip_close(zip), 0);  // compresses (deflate) and writes
}

TEST_F(BspLevelTest, ReadsTheMapInsideAPk3AsFromTheBspFile) {
  const std::string bytes = boxRoomBsp({256, 128, 96}).bytes();
  const std::filesystem::path bspFile = write("room.bsp", bytes);
  const std::filesystem::path pk3 = folder_ / "data.pk3";
  writeZip(pk3, "maps/room.bsp", bytes);

  const BspLevel direct = readBspLevel(bspFile);
  const BspLevel packed = readBspLevel(pk3, "maps/ROOM.bsp");  // names ignore case, as the game
  EXPECT_EQ(packed.mesh.positionsMeters, direct.mesh.positionsMeters);
  EXPECT_EQ(packed.mesh.triangles, direct.mesh.triangles);
  EXPECT_EQ(packed.mesh.parts[0].file, pk3.string() + ":maps/ROOM.bsp");

  try {
    readBspLevel(pk3, "maps/other.bsp");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), pk3.string() + ": no \"maps/other.bsp\" inside the archive");
  }
}

TEST_F(BspLevelTest, SceneLevelEntryNamesAMapInsideAPk3AndRoundTrips) {
  writeZip(folder_ / "data.pk3", "maps/room.bsp", boxRoomBsp({256, 128, 96}).bytes());
  const std::string text = R"({
  "probeproxy_scene": 1,
  "up": "Z",
  "meters_per_unit": 1.0,
  "level": [ { "mesh": "data.pk3", "map": "maps/room.bsp" } ],
  "probes": [
    {
      "name": "p",
      "capture": [4.0, 2.0, 1.6],
      "influence": { "kind": "sphere", "center": [4.0, 2.0, 1.6], "radius": 10.0 },
      "proxy": "auto"
    }
  ]
}
)";
  const std::filesystem::path file = write("room.scene.json", text);
  const Scene scene = readSceneFile(file);
  ASSERT_EQ(scene.level.size(), 1u);
  EXPECT_EQ(scene.level[0].map, "maps/room.bsp");
  EXPECT_EQ(sceneFileJson(scene), text);  // byte-exact round trip

  const LevelMesh level = loadLevel(scene);  // in metres whatever the scene's units
  EXPECT_EQ(level.triangles.size(), 12u);
  EXPECT_EQ(measureLevelMesh(level).boundsMaxMeters, glm::vec3(8.0f, 4.0f, 3.0f));

  const auto parseError = [&](const std::string& levelJson) {
    std::string bad = text;
    const std::string entry = R"([ { "mesh": "data.pk3", "map": "maps/room.bsp" } ])";
    bad.replace(bad.find(entry), entry.size(), levelJson);
    try {
      parseSceneFile(bad, file);
    } catch (const InputError& e) {
      return std::string(e.what()).substr(file.string().size() + 2);
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(parseError(R"([{"mesh": "data.pk3"}])"), "$.level[0]: expected member \"map\"");
  EXPECT_EQ(parseError(R"([{"mesh": "data.pk3", "map": "maps/room.txt"}])"),
            "$.level[0].map: expected the path of a .bsp inside the .pk3, e.g. "
            "\"maps/downer.bsp\", got \"maps/room.txt\"");
  EXPECT_EQ(parseError(R"([{"mesh": "room.bsp", "up": "Y"}])"),
            "$.level[0].up: unknown member (expected one of \"mesh\")");
  EXPECT_EQ(parseError(R"(["room.bsp"])"), "(no error)");
}

}  // namespace
}  // namespace probeproxy
