#include "geometry/level/bsp/bsp_level.h"

#include "core/errors/input_error.h"
#include "core/io/regular_file.h"
#include "core/scene/scene_limits.h"
#include "geometry/level/bsp/bezier_patch.h"
#include "geometry/level/bsp/bsp_lumps.h"
#include "geometry/level/bsp/bsp_surface_flags.h"
#include "geometry/level/bsp/pk3_archive.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

namespace probeproxy {

namespace {

// Record sizes and field offsets of qfiles.h's dshader_t, drawVert_t and dsurface_t.
constexpr std::size_t kShaderBytes = 72;    // char shader[64]; int surfaceFlags, contentFlags
constexpr std::size_t kDrawVertBytes = 44;  // xyz[3], st[2], lightmap[2], normal[3], color[4]
constexpr std::size_t kDrawIndexBytes = 4;
constexpr std::size_t kSurfaceBytes = 104;
constexpr std::size_t kSurfaceShader = 0, kSurfaceType = 8, kSurfaceFirstVert = 12,
                      kSurfaceNumVerts = 16, kSurfaceFirstIndex = 20, kSurfaceNumIndexes = 24,
                      kSurfacePatchWidth = 96, kSurfacePatchHeight = 100;

enum SurfaceType { kPlanar = 1, kPatch = 2, kTriangleSoup = 3, kFlare = 4 };

struct Shader {
  std::string name;
  BspSurfaceKind kind = BspSurfaceKind::Solid;
};

struct Face {
  int shader = 0;
  int type = 0;
  std::int64_t firstVert = 0, numVerts = 0, firstIndex = 0, numIndexes = 0;
  int patchWidth = 0, patchHeight = 0;
};

std::vector<Shader> readShaders(const BspLumps& lumps) {
  const std::span<const std::byte> bytes = lumps.bytes(BspLump::Shaders);
  const std::size_t count = lumps.recordCount(BspLump::Shaders, kShaderBytes);
  std::vector<Shader> shaders(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t at = i * kShaderBytes;
    char name[65] = {};
    std::memcpy(name, bytes.data() + at, 64);  // NUL-padded; name[64] ends an unpadded one
    shaders[i].name = name;
    shaders[i].kind = classifyBspShader(std::uint32_t(bspInt32(bytes, at + 64)),
                                        std::uint32_t(bspInt32(bytes, at + 68)));
  }
  return shaders;
}

Face readFace(std::span<const std::byte> bytes, std::size_t index) {
  const std::size_t at = index * kSurfaceBytes;
  Face f;
  f.shader = bspInt32(bytes, at + kSurfaceShader);
  f.type = bspInt32(bytes, at + kSurfaceType);
  f.firstVert = bspInt32(bytes, at + kSurfaceFirstVert);
  f.numVerts = bspInt32(bytes, at + kSurfaceNumVerts);
  f.firstIndex = bspInt32(bytes, at + kSurfaceFirstIndex);
  f.numIndexes = bspInt32(bytes, at + kSurfaceNumIndexes);
  f.patchWidth = bspInt32(bytes, at + kSurfacePatchWidth);
  f.patchHeight = bspInt32(bytes, at + kSurfacePatchHeight);
  return f;
}

// Everything a face refers to, checked before anything is read through it.
class FaceReader {
 public:
  FaceReader(const BspLumps& lumps, const BspLoadOptions& options)
      : lumps_(lumps),
        options_(options),
        verts_(lumps.bytes(BspLump::DrawVerts)),
        indexes_(lumps.bytes(BspLump::DrawIndexes)),
        vertCount_(std::int64_t(lumps.recordCount(BspLump::DrawVerts, kDrawVertBytes))),
        indexCount_(std::int64_t(lumps.recordCount(BspLump::DrawIndexes, kDrawIndexBytes))) {}

  // The face's triangles, in the file's vertex numbering made local (0..numVerts-1), and its
  // vertices in metres; wound counter-clockwise seen from the front.
  void appendTriangles(const Face& face, std::size_t faceIndex, std::vector<glm::vec3>& positions,
                       std::vector<glm::uvec3>& triangles) const {
    checkVertexRange(face, faceIndex);
    if (face.type == kPatch) {
      appendPatch(face, faceIndex, positions, triangles);
    } else {
      appendIndexed(face, faceIndex, positions, triangles);
    }
  }

 private:
  [[noreturn]] void failFace(std::size_t faceIndex, const std::string& problem) const {
    lumps_.fail(BspLump::Surfaces, "face " + std::to_string(faceIndex) + " " + problem);
  }

  void checkVertexRange(const Face& face, std::size_t faceIndex) const {
    if (face.firstVert < 0 || face.numVerts < 0 || face.firstVert + face.numVerts > vertCount_) {
      failFace(faceIndex, "uses vertices " + std::to_string(face.firstVert) + ".." +
                              std::to_string(face.firstVert + face.numVerts) + " of " +
                              std::to_string(vertCount_) + " in " +
                              bspLumpName(BspLump::DrawVerts));
    }
  }

  glm::dvec3 vertex(std::int64_t index) const {
    const std::size_t at = std::size_t(index) * kDrawVertBytes;
    const glm::dvec3 p(bspFloat(verts_, at), bspFloat(verts_, at + 4), bspFloat(verts_, at + 8));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      lumps_.fail(BspLump::DrawVerts,
                  "vertex " + std::to_string(index) + " has a non-finite coordinate");
    }
    return p;
  }

  void appendIndexed(const Face& face, std::size_t faceIndex, std::vector<glm::vec3>& positions,
                     std::vector<glm::uvec3>& triangles) const {
    if (face.firstIndex < 0 || face.numIndexes < 0 ||
        face.firstIndex + face.numIndexes > indexCount_) {
      failFace(faceIndex, "uses indexes " + std::to_string(face.firstIndex) + ".." +
                              std::to_string(face.firstIndex + face.numIndexes) + " of " +
                              std::to_string(indexCount_) + " in " +
                              bspLumpName(BspLump::DrawIndexes));
    }
    if (face.numIndexes % 3 != 0) {
      failFace(faceIndex, "has " + std::to_string(face.numIndexes) +
                              " indexes, not a whole number of triangles");
    }
    const auto base = std::uint32_t(positions.size());
    for (std::int64_t v = 0; v < face.numVerts; ++v) {
      positions.emplace_back(vertex(face.firstVert + v) * options_.metersPerUnit);
    }
    for (std::int64_t i = 0; i < face.numIndexes; i += 3) {
      std::uint32_t corner[3];
      for (int k = 0; k < 3; ++k) {
        const std::int32_t local =
            bspInt32(indexes_, std::size_t(face.firstIndex + i + k) * kDrawIndexBytes);
        if (local < 0 || local >= face.numVerts) {
          failFace(faceIndex, "index " + std::to_string(face.firstIndex + i + k) + " is " +
                                  std::to_string(local) + ", past its " +
                                  std::to_string(face.numVerts) + " vertices");
        }
        corner[k] = base + std::uint32_t(local);
      }
      // Quake 3 winds front faces clockwise (checked against the stored vertex normals);
      // swap two corners for counter-clockwise.
      triangles.emplace_back(corner[0], corner[2], corner[1]);
    }
  }

  void appendPatch(const Face& face, std::size_t faceIndex, std::vector<glm::vec3>& positions,
                   std::vector<glm::uvec3>& triangles) const {
    const int w = face.patchWidth, h = face.patchHeight;
    const bool oddSizes = w >= 3 && h >= 3 && w % 2 == 1 && h % 2 == 1;
    if (!oddSizes || std::int64_t(w) * h != face.numVerts) {
      failFace(faceIndex, "is a " + std::to_string(w) + " x " + std::to_string(h) + " patch with " +
                              std::to_string(face.numVerts) +
                              " control points (expected odd sizes of at least 3, "
                              "width x height points)");
    }
    std::vector<glm::dvec3> control;
    control.reserve(std::size_t(face.numVerts));
    for (std::int64_t v = 0; v < face.numVerts; ++v) control.push_back(vertex(face.firstVert + v));
    const TessellatedPatch patch = tessellateBezierPatch(control, w, h, options_.patchSubdivisions);
    const auto base = std::uint32_t(positions.size());
    for (const glm::dvec3& p : patch.points) positions.emplace_back(p * options_.metersPerUnit);
    // Unlike the game's polygons, a control grid runs counter-clockwise seen from the front
    // (checked against the stored vertex normals of the Nexuiz maps): no swap.
    for (const glm::uvec3& t : patch.triangles) triangles.push_back(t + glm::uvec3(base));
  }

  const BspLumps& lumps_;
  const BspLoadOptions& options_;
  std::span<const std::byte> verts_, indexes_;
  std::int64_t vertCount_, indexCount_;
};

void countKept(int type, BspFaceCounts& counts) {
  if (type == kPlanar) ++counts.polygons;
  if (type == kTriangleSoup) ++counts.meshes;
  if (type == kPatch) ++counts.patches;
}

void readFaces(const BspLumps& lumps, const BspLoadOptions& options, BspLevel& level) {
  const std::vector<Shader> shaders = readShaders(lumps);
  const std::span<const std::byte> surfaceBytes = lumps.bytes(BspLump::Surfaces);
  const std::size_t faceCount = lumps.recordCount(BspLump::Surfaces, kSurfaceBytes);
  const FaceReader reader(lumps, options);

  // Faces grouped by shader, so each shader's triangles are one contiguous LevelPart.
  std::vector<std::vector<std::size_t>> facesByShader(shaders.size());
  std::vector<Face> faces(faceCount);
  for (std::size_t i = 0; i < faceCount; ++i) {
    faces[i] = readFace(surfaceBytes, i);
    const Face& f = faces[i];
    if (f.type < kPlanar || f.type > kFlare) {
      lumps.fail(BspLump::Surfaces,
                 "face " + std::to_string(i) + " has unknown type " + std::to_string(f.type));
    }
    if (f.type == kFlare) {  // flares may have no shader worth checking: they are not drawn
      ++level.faces.billboards;
      continue;
    }
    if (f.shader < 0 || std::size_t(f.shader) >= shaders.size()) {
      lumps.fail(BspLump::Surfaces,
                 "face " + std::to_string(i) + " uses shader " + std::to_string(f.shader) + " of " +
                     std::to_string(shaders.size()) + " in " + bspLumpName(BspLump::Shaders));
    }
    facesByShader[std::size_t(f.shader)].push_back(i);
  }

  // Faces may share their vertices and indices, so a small file can name far more triangles
  // than it holds: count them as they are made and stop at the limit.
  const std::size_t maxTriangles = inputLimits().maxTriangles;
  LevelMesh& mesh = level.mesh;
  for (std::size_t s = 0; s < shaders.size(); ++s) {
    const Shader& shader = shaders[s];
    if (shader.kind == BspSurfaceKind::Skipped) {
      level.faces.skippedByFlags += facesByShader[s].size();
      continue;
    }
    const bool sky = shader.kind == BspSurfaceKind::Sky;
    std::vector<glm::uvec3>& into = sky ? mesh.skyTriangles : mesh.triangles;
    const auto first = std::uint32_t(into.size());
    for (const std::size_t i : facesByShader[s]) {
      reader.appendTriangles(faces[i], i, mesh.positionsMeters, into);
      const std::size_t made = mesh.triangles.size() + mesh.skyTriangles.size();
      if (made > maxTriangles || mesh.positionsMeters.size() > 3 * maxTriangles) {
        lumps.fail(BspLump::Surfaces,
                   "face " + std::to_string(i) + ": " + triangleLimitProblem(made));
      }
      if (sky) {
        ++level.faces.sky;
      } else {
        countKept(faces[i].type, level.faces);
      }
    }
    const auto count = std::uint32_t(into.size()) - first;
    if (!sky && count > 0) mesh.parts.push_back({shader.name, lumps.file(), first, count});
  }
}

std::string entityText(const BspLumps& lumps) {
  const std::span<const std::byte> bytes = lumps.bytes(BspLump::Entities);
  std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) text.resize(nul);
  return text;
}

std::vector<std::byte> readWholeBinaryFile(const std::filesystem::path& file) {
  requireRegularFile(file, "BSP file");
  std::error_code ec;
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open");
  const auto size = std::filesystem::file_size(file, ec);
  if (size > inputLimits().maxFileBytes())
    throw InputError(file, fileLimitProblem("BSP file", size));
  std::vector<std::byte> bytes(size);
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
  if (!in) throw InputError(file, "cannot read");
  return bytes;
}

}  // namespace

MeasureSettings quake3Player(double metersPerUnit) {
  MeasureSettings player;
  player.stepHeightMeters = 18.0 * metersPerUnit;
  player.headClearanceMeters = 56.0 * metersPerUnit;
  player.eyeHeightMeters = 50.0 * metersPerUnit;
  return player;
}

BspLevel parseBspLevel(std::span<const std::byte> bytes, const std::filesystem::path& file,
                       const BspLoadOptions& options) {
  if (!(options.metersPerUnit > 0.0) || !std::isfinite(options.metersPerUnit) ||
      options.patchSubdivisions < 1 || options.patchSubdivisions > 64) {
    throw InputError(file,
                     "BSP load options: metres per unit must be positive and patch "
                     "subdivisions 1..64");
  }
  const BspLumps lumps(bytes, file);
  BspLevel level;
  readFaces(lumps, options, level);
  level.entities = parseBspEntities(entityText(lumps), file);
  level.spawnPoints = bspSpawnPoints(level.entities, options.metersPerUnit, file);
  level.lights = bspLights(level.entities, options.metersPerUnit, file);
  level.mesh.gamePlayer = quake3Player(options.metersPerUnit);
  level.mesh.facesOneSided = true;
  return level;
}

BspLevel readBspLevel(const std::filesystem::path& file, const std::filesystem::path& mapInArchive,
                      const BspLoadOptions& options) {
  if (mapInArchive.empty()) return parseBspLevel(readWholeBinaryFile(file), file, options);
  const std::vector<std::byte> bytes = readFileFromPk3(file, mapInArchive);
  return parseBspLevel(bytes, file.string() + ":" + mapInArchive.generic_string(), options);
}

}  // namespace probeproxy
