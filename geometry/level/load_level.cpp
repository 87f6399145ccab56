#include "geometry/level/load_level.h"

#include "core/errors/input_error.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace probeproxy {

namespace {

std::string lowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void requireReadableMeshFile(const std::filesystem::path& file) {
  static const char* const kFormats[] = {".glb", ".gltf", ".obj", ".ply", ".off"};
  const std::string ext = lowerExtension(file);
  if (std::find(std::begin(kFormats), std::end(kFormats), ext) == std::end(kFormats)) {
    throw InputError(file, "unsupported mesh format '" + ext +
                               "' (expected .glb, .gltf, .obj, .ply or .off)");
  }
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(file, "mesh file not found");
  if (!std::filesystem::is_regular_file(file, ec)) throw InputError(file, "not a regular file");
  if (std::filesystem::file_size(file, ec) == 0) throw InputError(file, "mesh file is empty");
}

std::string describeVertex(const aiVector3D& v) {
  std::ostringstream s;
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// Assimp strips the mesh format's own validation down to "it parsed"; we still refuse what
// would poison every ray: non-finite coordinates and faces pointing at missing vertices.
void appendAssimpMesh(const aiMesh& mesh, const std::filesystem::path& file, UpAxis fileUp,
                      double metersPerUnit, LevelMesh& out) {
  LevelPart part;
  part.name = mesh.mName.length > 0 ? mesh.mName.C_Str() : "mesh" + std::to_string(out.parts.size());
  part.file = file;
  part.firstTriangle = static_cast<std::uint32_t>(out.triangles.size());

  const auto base = static_cast<std::uint32_t>(out.positionsMeters.size());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D& v = mesh.mVertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      throw InputError(file, "mesh '" + part.name + "' vertex " + std::to_string(i) +
                                 " has a non-finite coordinate " + describeVertex(v));
    }
    const glm::dvec3 inFile = glm::dvec3(v.x, v.y, v.z) * metersPerUnit;
    const glm::dvec3 world = fileUp == UpAxis::Y ? zUpFromYUp(inFile) : inFile;
    out.positionsMeters.emplace_back(world);
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines carry no surface
    for (unsigned k = 0; k < 3; ++k) {
      if (face.mIndices[k] >= mesh.mNumVertices) {
        throw InputError(file, "mesh '" + part.name + "' face " + std::to_string(f) +
                                   " refers to vertex " + std::to_string(face.mIndices[k]) +
                                   " of " + std::to_string(mesh.mNumVertices));
      }
    }
    out.triangles.emplace_back(base + face.mIndices[0], base + face.mIndices[1],
                               base + face.mIndices[2]);
  }
  part.triangleCount = static_cast<std::uint32_t>(out.triangles.size()) - part.firstTriangle;
  if (part.triangleCount > 0) out.parts.push_back(std::move(part));
}

}  // namespace

LevelMesh loadLevelMeshFile(const std::filesystem::path& file, UpAxis fileUp,
                            double metersPerUnit) {
  requireReadableMeshFile(file);

  Assimp::Importer importer;
  // Points and lines are dropped; nothing is welded, fixed or removed, so what we measure is
  // the level as authored. Node transforms are baked so glTF scenes land where Blender had them.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      file.string(), aiProcess_Triangulate | aiProcess_PreTransformVertices |
                         aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (scene == nullptr) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = "unknown reason";
    throw InputError(file, "malformed mesh: " + reason);
  }

  LevelMesh level;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    appendAssimpMesh(*scene->mMeshes[m], file, fileUp, metersPerUnit, level);
  }
  if (level.triangles.empty()) throw InputError(file, "mesh has no triangles");
  return level;
}

LevelMesh loadLevel(const Scene& scene) {
  if (scene.level.empty()) throw InputError(scene.file, "the level lists no meshes");
  LevelMesh level;
  for (const LevelMeshRef& ref : scene.level) {
    appendLevelMesh(level, loadLevelMeshFile(ref.path, ref.up, scene.metersPerUnit));
  }
  return level;
}

}  // namespace probeproxy
