// write_fuzz_seeds OUT: the generated part of each fuzz target's seed corpus, OUT/<target>/.
// Small valid files of every kind the readers take (a libFuzzer run mutates these far faster
// than a real map), written by the project's own writers where it has them so that the seeds
// are what probeproxy itself reads back. scripts/fuzz.sh adds the suite's and the corpus'
// files and the broken variants kept under tests/e2e/hostile/.
#include "../unit/synthetic_bsp.h"
#include "core/cube/cube_face.h"
#include "core/cube/cubemap.h"
#include "core/cube/cubemap_io.h"
#include "geometry/level/write_level_mesh.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>
#include <zip.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using namespace probeproxy;

namespace {

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// A 4 x 3 x 2.5 m room with a pillar: twelve walls' worth of triangles, a few parts' worth of
// structure for the mutator to work on.
LevelMesh roomWithPillar() {
  LevelMesh level;
  const auto box = [&](glm::vec3 lo, glm::vec3 hi) {
    const auto base = std::uint32_t(level.positionsMeters.size());
    for (int i = 0; i < 8; ++i) {
      level.positionsMeters.push_back(
          {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    }
    const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
      level.triangles.push_back({base + q[0], base + q[1], base + q[2]});
      level.triangles.push_back({base + q[0], base + q[2], base + q[3]});
    }
  };
  box({0, 0, 0}, {4, 3, 2.5f});
  box({1.8f, 1.3f, 0}, {2.2f, 1.7f, 2.5f});
  level.parts.push_back({"room", "seed", 0, std::uint32_t(level.triangles.size())});
  return level;
}

// The .glb's JSON with its binary chunk moved into a base64 data URI: a .gltf that is one
// self-contained file, as the loader's fuzz target needs.
std::string gltfFromGlb(const std::string& glb) {
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, glb.data() + at, 4);
    return v;
  };
  const std::uint32_t jsonLength = u32(12);
  nlohmann::json gltf = nlohmann::json::parse(glb.substr(20, jsonLength));
  const std::size_t binAt = 20 + jsonLength;
  const std::string bin = glb.substr(binAt + 8, u32(binAt));
  gltf["buffers"][0]["uri"] =
      "data:application/octet-stream;base64," + OIIO::Strutil::base64_encode(bin);
  return gltf.dump(1);
}

testing::SyntheticBsp seedBsp() {
  testing::SyntheticBsp bsp = testing::boxRoomBsp({256, 192, 128});
  bsp.entities +=
      "{\n\"classname\" \"info_player_deathmatch\"\n\"origin\" \"64 64 24\"\n}\n"
      "{\n\"classname\" \"light\"\n\"origin\" \"128 96 100\"\n\"light\" \"300\"\n}\n";
  bsp.shaders.push_back({"textures/test/sky", 0x4, 1});            // SURF_SKY
  bsp.shaders.push_back({"textures/common/clip", 0x80, 0x10000});  // nodraw, playerclip
  bsp.addPolygon(1, {{0, 0, 128}, {256, 0, 128}, {256, 192, 128}});
  bsp.addPolygon(2, {{10, 10, 0}, {20, 10, 0}, {20, 20, 0}});
  // An arch: one 3 x 3 Bezier patch.
  bsp.addPatch(0, 3, 3,
               {{100, 0, 0},
                {100, 0, 64},
                {100, 0, 96},
                {128, 0, 0},
                {128, 0, 64},
                {128, 0, 128},
                {156, 0, 0},
                {156, 0, 64},
                {156, 0, 96}});
  return bsp;
}

std::string pk3Holding(const std::string& entryName, const std::string& bytes,
                       const fs::path& file) {
  fs::create_directories(file.parent_path());
  int error = 0;
  zip_t* zip = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (!zip) throw std::runtime_error("cannot create " + file.string());
  zip_source_t* source = zip_source_buffer(zip, bytes.data(), bytes.size(), 0);
  if (!source || zip_file_add(zip, entryName.c_str(), source, ZIP_FL_ENC_UTF_8) < 0 ||
      zip_close(zip) != 0) {
    throw std::runtime_error("cannot write " + file.string());
  }
  return readBytes(file);
}

// A small cube whose faces differ, so that layouts that swap faces read differently.
Cubemap seedCube(int size) {
  std::array<std::vector<float>, kCubeFaceCount> rgb;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    for (int i = 0; i < size * size; ++i) {
      rgb[f].insert(rgb[f].end(), {0.2f * float(f), float(i % size) / float(size),
                                   float(i / size) / float(size)});
    }
  }
  return Cubemap::fromFaces(size, std::move(rgb));
}

void writeImage(const fs::path& file, int width, int height, int channels, OIIO::TypeDesc type,
                const void* pixels) {
  fs::create_directories(file.parent_path());
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out || !out->open(file.string(), OIIO::ImageSpec(width, height, channels, type)) ||
      !out->write_image(type, pixels) || !out->close()) {
    throw std::runtime_error("cannot write " + file.string());
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_fuzz_seeds OUT\n";
    return 2;
  }
  const fs::path out = argv[1];
  const fs::path scratch = out / "scratch";
  fs::create_directories(scratch);

  const LevelMesh level = roomWithPillar();
  for (const char* ext : {".glb", ".obj", ".ply", ".off"}) {
    const fs::path file = scratch / (std::string("room") + ext);
    writeLevelMeshFile(level, file, ext == std::string(".glb") ? UpAxis::Y : UpAxis::Z);
    writeBytes(out / ("level_" + std::string(ext + 1)) / file.filename(), readBytes(file));
  }
  writeBytes(out / "level_gltf" / "room.gltf", gltfFromGlb(readBytes(scratch / "room.glb")));

  const std::string bsp = seedBsp().bytes();
  writeBytes(out / "bsp" / "room.bsp", bsp);
  writeBytes(out / "pk3" / "room.pk3", pk3Holding("maps/fuzz.bsp", bsp, scratch / "room.pk3"));

  const Cubemap cube = seedCube(4);
  writeCubemapImage(cube, scratch / "hcross.exr", CubemapImageLayout::HorizontalCross);
  writeCubemapImage(cube, scratch / "vcross.exr", CubemapImageLayout::VerticalCross);
  writeCubemapImage(cube, scratch / "equirect.exr", CubemapImageLayout::Equirect);
  for (const char* name : {"hcross", "vcross", "equirect"}) {
    // Re-encoded as Radiance .hdr, the format the image target reads.
    auto in = OIIO::ImageInput::open((scratch / (std::string(name) + ".exr")).string());
    const OIIO::ImageSpec spec = in->spec();
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * 3);
    in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data());
    writeImage(out / "cubemap_image" / (std::string(name) + ".hdr"), spec.width, spec.height, 3,
               OIIO::TypeDesc::FLOAT, pixels.data());
  }

  std::string faces;
  for (int f = 0; f < 6; ++f) {
    std::vector<std::uint8_t> pixels(4 * 4 * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::uint8_t(40 * f + 3 * i);
    const fs::path png = scratch / ("face" + std::to_string(f) + ".png");
    writeImage(png, 4, 4, 3, OIIO::TypeDesc::UINT8, pixels.data());
    if (f) faces += "--probeproxy-face--";
    faces += readBytes(png);
  }
  writeBytes(out / "cubemap_faces" / "six_4px.faces", faces);
  fs::remove_all(scratch);
  return 0;
}
