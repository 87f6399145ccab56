#pragma once
// Small Quake 3 BSP files (IBSP 46) written in the test, so the loader is tested without
// game data. Only the lumps the loader reads are filled; the others are empty, placed at the
// end of the file. Lumps are laid out in lump order after the header.

#include <glm/vec3.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace probeproxy::testing {

struct SyntheticShader {
  std::string name;
  std::uint32_t surfaceFlags = 0;
  std::uint32_t contentFlags = 1;  // CONTENTS_SOLID
};

struct SyntheticFace {
  int shader = 0;
  int type = 1;  // 1 polygon, 2 patch, 3 mesh, 4 flare
  int firstVert = 0, numVerts = 0, firstIndex = 0, numIndexes = 0;
  int patchWidth = 0, patchHeight = 0;
};

struct SyntheticBsp {
  std::string entities;
  std::vector<SyntheticShader> shaders;
  std::vector<glm::vec3> vertsUnits;  // game units
  std::vector<std::int32_t> indexes;
  std::vector<SyntheticFace> faces;

  // A face from `corners` (game units) as the game stores it: a polygon fan wound
  // clockwise seen from the front, i.e. `corners` listed counter-clockwise seen from the
  // front are written in reverse.
  void addPolygon(int shader, const std::vector<glm::vec3>& cornersCounterClockwise) {
    SyntheticFace f;
    f.shader = shader;
    f.type = 1;
    f.firstVert = int(vertsUnits.size());
    f.numVerts = int(cornersCounterClockwise.size());
    f.firstIndex = int(indexes.size());
    for (const glm::vec3& c : cornersCounterClockwise) vertsUnits.push_back(c);
    for (int i = 1; i + 1 < f.numVerts; ++i) {
      indexes.insert(indexes.end(), {0, i + 1, i});  // clockwise
    }
    f.numIndexes = int(indexes.size()) - f.firstIndex;
    faces.push_back(f);
  }

  void addPatch(int shader, int width, int height, const std::vector<glm::vec3>& control) {
    SyntheticFace f;
    f.shader = shader;
    f.type = 2;
    f.firstVert = int(vertsUnits.size());
    f.numVerts = int(control.size());
    f.patchWidth = width;
    f.patchHeight = height;
    vertsUnits.insert(vertsUnits.end(), control.begin(), control.end());
    faces.push_back(f);
  }

  // Byte offset of each lump, as bytes() lays them out.
  struct Layout {
    std::uint32_t offset[17] = {}, length[17] = {};
    std::uint32_t total = 0;
  };

  Layout layout() const {
    Layout l;
    const std::uint32_t sizes[17] = {std::uint32_t(entities.size() + 1),
                                     std::uint32_t(shaders.size() * 72),
                                     0,
                                     0,
                                     0,
                                     0,
                                     0,
                                     0,
                                     0,
                                     0,
                                     std::uint32_t(vertsUnits.size() * 44),
                                     std::uint32_t(indexes.size() * 4),
                                     0,
                                     std::uint32_t(faces.size() * 104),
                                     0,
                                     0,
                                     0};
    std::uint32_t at = 8 + 8 * 17;
    for (int i = 0; i < 17; ++i) {
      l.offset[i] = at;
      l.length[i] = sizes[i];
      at += sizes[i];
    }
    l.total = at;
    return l;
  }

  std::string bytes() const {
    const Layout l = layout();
    std::string out(l.total, '\0');
    const auto put32 = [&](std::size_t at, std::uint32_t v) {
      for (int k = 0; k < 4; ++k) out[at + k] = char((v >> (8 * k)) & 0xff);  // little-endian
    };
    const auto putFloat = [&](std::size_t at, float f) {
      std::uint32_t v;
      std::memcpy(&v, &f, 4);
      put32(at, v);
    };
    std::memcpy(out.data(), "IBSP", 4);
    put32(4, 46);
    for (int i = 0; i < 17; ++i) {
      put32(8 + 8 * i, l.offset[i]);
      put32(12 + 8 * i, l.length[i]);
    }
    std::memcpy(out.data() + l.offset[0], entities.data(), entities.size());
    for (std::size_t i = 0; i < shaders.size(); ++i) {
      const std::size_t at = l.offset[1] + i * 72;
      std::memcpy(out.data() + at, shaders[i].name.data(),
                  std::min<std::size_t>(63, shaders[i].name.size()));
      put32(at + 64, shaders[i].surfaceFlags);
      put32(at + 68, shaders[i].contentFlags);
    }
    for (std::size_t i = 0; i < vertsUnits.size(); ++i) {
      const std::size_t at = l.offset[10] + i * 44;
      for (int k = 0; k < 3; ++k) putFloat(at + 4 * k, vertsUnits[i][k]);
    }
    for (std::size_t i = 0; i < indexes.size(); ++i) put32(l.offset[11] + i * 4, indexes[i]);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const std::size_t at = l.offset[13] + i * 104;
      const SyntheticFace& f = faces[i];
      put32(at + 0, f.shader);
      put32(at + 4, std::uint32_t(-1));  // no fog
      put32(at + 8, f.type);
      put32(at + 12, f.firstVert);
      put32(at + 16, f.numVerts);
      put32(at + 20, f.firstIndex);
      put32(at + 24, f.numIndexes);
      put32(at + 96, f.patchWidth);
      put32(at + 100, f.patchHeight);
    }
    return out;
  }
};

// A closed box room, [0, size] in game units, its six walls facing inwards, one shader.
inline SyntheticBsp boxRoomBsp(glm::vec3 size) {
  SyntheticBsp bsp;
  bsp.entities = "{\n\"classname\" \"worldspawn\"\n}\n";
  bsp.shaders = {{"textures/test/wall", 0, 1}};
  const float X = size.x, Y = size.y, Z = size.z;
  // Each wall's corners counter-clockwise seen from inside the room.
  bsp.addPolygon(0, {{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}});  // floor, normal +z
  bsp.addPolygon(0, {{0, 0, Z}, {0, Y, Z}, {X, Y, Z}, {X, 0, Z}});  // ceiling, -z
  bsp.addPolygon(0, {{0, 0, 0}, {0, Y, 0}, {0, Y, Z}, {0, 0, Z}});  // x = 0, +x
  bsp.addPolygon(0, {{X, 0, 0}, {X, 0, Z}, {X, Y, Z}, {X, Y, 0}});  // x = X, -x
  bsp.addPolygon(0, {{0, 0, 0}, {0, 0, Z}, {X, 0, Z}, {X, 0, 0}});  // y = 0, +y
  bsp.addPolygon(0, {{0, Y, 0}, {X, Y, 0}, {X, Y, Z}, {0, Y, Z}});  // y = Y, -y
  return bsp;
}

}  // namespace probeproxy::testing
