#include "geometry/level/write_level_mesh.h"

#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"

#include <assimp/scene.h>
#include <assimp/Exporter.hpp>

#include <algorithm>
#include <fstream>
#include <limits>
#include <map>
#include <memory>

namespace probeproxy {

namespace {

glm::vec3 toFileFrame(glm::vec3 world, UpAxis fileUp) {
  return fileUp == UpAxis::Y ? yUpFromZUp(world) : world;
}

// One aiMesh per LevelPart, so names survive a round trip; parts cover the triangles in order.
std::unique_ptr<aiScene> toAssimpScene(const LevelMesh& level, UpAxis fileUp) {
  std::vector<LevelPart> parts = level.parts;
  if (parts.empty()) {
    parts.push_back({"level", {}, 0, static_cast<std::uint32_t>(level.triangles.size())});
  }
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("root");
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };
  scene->mNumMeshes = static_cast<unsigned>(parts.size());
  scene->mMeshes = new aiMesh*[parts.size()];
  // One node per part, named like it: readers (Blender, ours) name objects after nodes.
  scene->mRootNode->mNumChildren = static_cast<unsigned>(parts.size());
  scene->mRootNode->mChildren = new aiNode*[parts.size()];

  for (std::size_t p = 0; p < parts.size(); ++p) {
    // Each part gets its own compact vertex list, in first-use order.
    std::map<std::uint32_t, unsigned> local;
    std::vector<std::uint32_t> used;
    for (std::uint32_t t = 0; t < parts[p].triangleCount; ++t) {
      const glm::uvec3& tri = level.triangles[parts[p].firstTriangle + t];
      for (int k = 0; k < 3; ++k) {
        if (local.emplace(tri[k], static_cast<unsigned>(used.size())).second)
          used.push_back(tri[k]);
      }
    }
    auto* mesh = new aiMesh();
    mesh->mName = parts[p].name;
    mesh->mMaterialIndex = 0;
    mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    mesh->mNumVertices = static_cast<unsigned>(used.size());
    mesh->mVertices = new aiVector3D[used.size()];
    for (std::size_t v = 0; v < used.size(); ++v) {
      const glm::vec3 q = toFileFrame(level.positionsMeters[used[v]], fileUp);
      mesh->mVertices[v] = aiVector3D(q.x, q.y, q.z);
    }
    mesh->mNumFaces = parts[p].triangleCount;
    mesh->mFaces = new aiFace[mesh->mNumFaces];
    for (unsigned t = 0; t < mesh->mNumFaces; ++t) {
      const glm::uvec3& tri = level.triangles[parts[p].firstTriangle + t];
      mesh->mFaces[t].mNumIndices = 3;
      mesh->mFaces[t].mIndices = new unsigned[3]{local[tri.x], local[tri.y], local[tri.z]};
    }
    scene->mMeshes[p] = mesh;
    auto* node = new aiNode(parts[p].name);
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{static_cast<unsigned>(p)};
    scene->mRootNode->mChildren[p] = node;
  }
  return scene;
}

// Assimp has no OFF writer; the format is a header line and two lists.
void writeOff(const LevelMesh& level, const std::filesystem::path& file, UpAxis fileUp) {
  std::ofstream out(file, std::ios::trunc);
  out.precision(std::numeric_limits<float>::max_digits10);
  out << "OFF\n" << level.positionsMeters.size() << ' ' << level.triangles.size() << " 0\n";
  for (const glm::vec3& p : level.positionsMeters) {
    const glm::vec3 q = toFileFrame(p, fileUp);
    out << q.x << ' ' << q.y << ' ' << q.z << '\n';
  }
  for (const glm::uvec3& t : level.triangles)
    out << "3 " << t.x << ' ' << t.y << ' ' << t.z << '\n';
  out.close();
  if (!out) throw InputError(file, "cannot write");
}

}  // namespace

void writeLevelMeshFile(const LevelMesh& level, const std::filesystem::path& file, UpAxis fileUp) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  static const std::map<std::string, std::string> kAssimpFormat = {
      {".glb", "glb2"}, {".obj", "objnomtl"}, {".ply", "plyb"}};

  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    if (ext == ".off") return writeOff(level, tmp, fileUp);
    const auto format = kAssimpFormat.find(ext);
    if (format == kAssimpFormat.end())
      throw InputError(file, "cannot write mesh format '" + ext + "'");
    const std::unique_ptr<aiScene> scene = toAssimpScene(level, fileUp);
    Assimp::Exporter exporter;
    if (exporter.Export(scene.get(), format->second, tmp.string()) != AI_SUCCESS) {
      throw InputError(file, std::string("cannot write: ") + exporter.GetErrorString());
    }
  });
}

}  // namespace probeproxy
