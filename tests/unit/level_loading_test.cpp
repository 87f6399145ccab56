#include "core/errors/input_error.h"
#include "geometry/builtin/box_room.h"
#include "geometry/level/load_level.h"
#include "geometry/level/write_level_mesh.h"
#include "test_files.h"

#include <gmock/gmock.h>

namespace probeproxy {
namespace {

using ::testing::HasSubstr;

// What real levels contain: two rooms sharing vertices, an edge used by three triangles
// (non-manifold), an open hole, a duplicated vertex, a zero-area triangle, a collinear one,
// and coordinates that are not round numbers.
LevelMesh messyLevel() {
  LevelMesh level = boxRoom({-1.25f, -2.5f, 0.0f}, {3.125f, 1.0f, 2.7f}, "room");
  level.triangles.pop_back();  // a hole in the ceiling
  level.parts[0].triangleCount -= 1;
  LevelMesh fin;
  fin.positionsMeters = {{0.1f, 0.2f, 0.3f},
                         {1.7f, 0.2f, 0.3f},
                         {0.1f, 1.3f, 2.9f},
                         {0.1f, 0.2f, 0.3f},   // duplicate of vertex 0
                         {0.9f, 0.2f, 0.3f}};  // on the edge 0-1: collinear triangle below
  fin.triangles = {{0, 1, 2}, {3, 1, 2}, {0, 0, 2}, {0, 4, 1}};  // 0-1-2 and 3-1-2 overlap
  fin.parts = {{"fin", {}, 0, 4}};
  appendLevelMesh(level, fin);
  return level;
}

// Readers may split, share or duplicate vertices; what must survive is every triangle's
// corners, in order, bit for bit.
std::vector<glm::vec3> triangleCorners(const LevelMesh& level) {
  std::vector<glm::vec3> corners;
  for (const glm::uvec3& t : level.triangles) {
    for (int k = 0; k < 3; ++k) corners.push_back(level.positionsMeters[t[k]]);
  }
  return corners;
}

class LevelLoading : public testing::TempFolderTest {};

class LevelRoundTrip : public LevelLoading, public ::testing::WithParamInterface<const char*> {};

TEST_P(LevelRoundTrip, MessyLevelReadsBackBitExact) {
  const LevelMesh written = messyLevel();
  const std::filesystem::path file = folder_ / (std::string("level") + GetParam());
  for (UpAxis up : {UpAxis::Z, UpAxis::Y}) {
    writeLevelMeshFile(written, file, up);
    const LevelMesh read = loadLevelMeshFile(file, up, 1.0);
    const std::vector<glm::vec3> expected = triangleCorners(written),
                                 actual = triangleCorners(read);
    ASSERT_EQ(actual.size(), expected.size()) << GetParam();
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(actual[i], expected[i])
          << GetParam() << " corner " << i << " of triangle " << i / 3;
    }
    EXPECT_EQ(measureLevelMesh(read).degenerateTriangles, 2u);  // nothing was dropped or fixed
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, LevelRoundTrip,
                         ::testing::Values(".glb", ".obj", ".ply", ".off"),
                         [](const auto& p) { return std::string(p.param + 1); });

TEST_F(LevelLoading, GlbKeepsMeshNames) {
  writeLevelMeshFile(messyLevel(), folder_ / "named.glb", UpAxis::Y);
  const LevelMesh read = loadLevelMeshFile(folder_ / "named.glb", UpAxis::Y, 1.0);
  ASSERT_EQ(read.parts.size(), 2u);
  EXPECT_EQ(read.parts[0].name, "room");
  EXPECT_EQ(read.parts[1].name, "fin");
}

TEST_F(LevelLoading, GltfIsReadAsYUp) {
  // One triangle, written by hand as glTF 2.0 with an embedded buffer: (0,0,0) (1,0,0) (0,2,-3)
  // in glTF's Y-up frame. In the Z-up world (x, y, z) -> (x, -z, y): (0, 3, 2).
  const std::string gltf = R"({
    "asset": {"version": "2.0"},
    "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "tri"}],
    "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, -3], "max": [1, 2, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAEAAAEDA"}]
  })";
  const LevelMesh read = loadLevelMeshFile(write("tri.gltf", gltf), UpAxis::Y, 1.0);
  ASSERT_EQ(read.triangles.size(), 1u);
  EXPECT_EQ(triangleCorners(read), (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 3, 2}}));
}

TEST_F(LevelLoading, MetersPerUnitScalesALevelInCentimetres) {
  const auto file = write("cm.obj", "v 0 0 0\nv 100 0 0\nv 0 250 0\nf 1 2 3\n");
  const LevelMesh read = loadLevelMeshFile(file, UpAxis::Z, 0.01);
  EXPECT_EQ(triangleCorners(read), (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 2.5f, 0}}));
}

TEST_F(LevelLoading, QuadsAndPolygonsAreTriangulated) {
  const auto file =
      write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\nf 1 2 3 5 4\n");
  EXPECT_EQ(loadLevelMeshFile(file, UpAxis::Z, 1.0).triangles.size(), 3u);
}

// Our OFF reader (geometry/level/off_file.h) on the variants real exporters write: the same
// triangle from plain OFF, COFF with colours, NOFF with normals, comments, counts on the
// keyword's line, a face with its colour, and no keyword at all.
TEST_F(LevelLoading, OffVariantsReadTheSameTriangle) {
  const std::vector<glm::vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 2.5f, 0}};
  const char* variants[] = {
      "OFF\n3 1 0\n0 0 0\n1 0 0\n0 2.5 0\n3 0 1 2\n",
      "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 2.5 0 0 0 255 255\n3 0 1 2\n",
      "NOFF # normals follow\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 2.5 0 0 0 1\n3 0 1 2 1 0 0\n",
      "OFF 3 1 0\n# a comment line\n\n0 0 0\n1 0 0 # trailing\n0 2.5 0\n3 0 1 2\n",
      "3 1 0\n0 0 0\n1 0 0\n0 2.5 0\n3 0 1 2\n",
      "OFF\n3 1 0\n+0 0 0\n1.0e0 0 0\n0 +2.5 0\n3 0 1 2\n",
  };
  int n = 0;
  for (const char* text : variants) {
    const auto file = write("variant" + std::to_string(n++) + ".off", text);
    EXPECT_EQ(triangleCorners(loadLevelMeshFile(file, UpAxis::Z, 1.0)), triangle) << text;
  }
}

struct BadMesh {
  const char* name;
  const char* text;
  const char* problem;  // what the one-line message must say
};

class LevelLoadingRejects : public LevelLoading, public ::testing::WithParamInterface<BadMesh> {};

TEST_P(LevelLoadingRejects, WithOneLineNamingTheFile) {
  const BadMesh& bad = GetParam();
  const std::filesystem::path file = write(bad.name, bad.text);
  try {
    loadLevelMeshFile(file, UpAxis::Z, 1.0);
    FAIL() << "expected an InputError for " << bad.name;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file);
    EXPECT_THAT(e.what(), HasSubstr(file.string() + ": "));
    EXPECT_THAT(e.problem(), HasSubstr(bad.problem));
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(
    BadInputs, LevelLoadingRejects,
    ::testing::Values(
        BadMesh{"nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n",
                "vertex 1 has a non-finite coordinate"},
        BadMesh{"inf.ply",
                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                "end_header\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n",
                "has a non-finite coordinate"},
        BadMesh{"out_of_range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "malformed mesh"},
        BadMesh{"binary.off", "OFF BINARY\n", "binary OFF is not read"},
        BadMesh{"four_d.off", "4OFF\n1 0 0\n0 0 0 1\n", "4OFF (4D or n-dimensional) is not read"},
        BadMesh{"short_colour.off", "COFF\n3 1 0\n0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                "not a complete off file"},
        // Read only as the format its extension names: no other importer tries its content.
        BadMesh{"garbage.obj", "this is not a mesh\n\x01\x02\x03 at all\n",
                "malformed mesh: not a .obj file (its content does not start as one)"},
        BadMesh{"opengex_text.gltf", "Metric {float {1.0}}\n", "malformed mesh: not a .gltf file"},
        // Assimp 5.2.5 reads through a null pointer on such a primitive drawn as lines.
        BadMesh{"no_positions.gltf",
                "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [{\"primitives\": "
                "[{\"attributes\": {}, \"mode\": 2}]}]}",
                "malformed mesh: glTF mesh 0 primitive 0 has no POSITION attribute"},
        BadMesh{"line_loop.gltf",
                "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [{\"primitives\": "
                "[{\"attributes\": {\"POSITION\": 0}, \"mode\": 2}]}]}",
                "malformed mesh: glTF mesh 0 primitive 0 is a line loop (mode 2)"},
        BadMesh{
            "huge_buffers.gltf",
            "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"big.bin\", "
            "\"byteLength\": 5000000000}]}",
            "its buffers' declared byteLength is 4769 MiB, over the limit of 1024 MiB (raise it "
            "with --max-file-mb)"},
        BadMesh{"index_past_end.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n", "malformed mesh"},
        BadMesh{"lines_only.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n", "mesh has no triangles"},
        BadMesh{"empty.glb", "", "mesh file is empty"},
        BadMesh{"broken.glb", "glTF\x02\0\0\0garbage", "malformed mesh"},
        BadMesh{"level.stl", "solid x\nendsolid x\n", "unsupported mesh format '.stl'"}),
    [](const auto& p) {
      std::string n = p.param.name;
      std::replace(n.begin(), n.end(), '.', '_');
      return n;
    });

TEST_F(LevelLoading, MissingFileIsNamed) {
  const std::filesystem::path file = folder_ / "no_such_level.glb";
  try {
    loadLevelMeshFile(file, UpAxis::Y, 1.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": mesh file not found");
  }
}

TEST_F(LevelLoading, SceneLevelConcatenatesMeshesInOrder) {
  Scene scene;
  scene.file = folder_ / "two.scene.json";
  writeLevelMeshFile(boxRoom({0, 0, 0}, {1, 1, 1}, "a"), folder_ / "a.obj", UpAxis::Z);
  writeLevelMeshFile(boxRoom({5, 0, 0}, {6, 1, 1}, "b"), folder_ / "b.glb", UpAxis::Y);
  scene.level = {{folder_ / "a.obj", "a.obj", UpAxis::Z, false, {}},
                 {folder_ / "b.glb", "b.glb", UpAxis::Y, false, {}}};
  const LevelMesh level = loadLevel(scene);
  EXPECT_EQ(level.triangles.size(), 24u);
  ASSERT_EQ(level.parts.size(), 2u);
  EXPECT_EQ(level.parts[1].firstTriangle, 12u);
  EXPECT_EQ(measureLevelMesh(level).boundsMaxMeters, glm::vec3(6, 1, 1));
}

}  // namespace
}  // namespace probeproxy
