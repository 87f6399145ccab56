#include "geometry/level/load_level.h"

#include "core/errors/input_error.h"
#include "core/io/regular_file.h"
#include "core/scene/scene_limits.h"
#include "geometry/level/bsp/bsp_level.h"
#include "geometry/level/gltf_claims.h"
#include "geometry/level/obj_material_libraries.h"
#include "geometry/level/polygon_soup_file.h"

#include <assimp/BaseImporter.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>

namespace probeproxy {

namespace {

std::string lowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void requireReadableMeshFile(const std::filesystem::path& file) {
  static const char* const kFormats[] = {".glb", ".gltf", ".obj", ".ply", ".off"};
  const std::string ext = lowerExtension(file);
  if (std::find(std::begin(kFormats), std::end(kFormats), ext) == std::end(kFormats)) {
    throw InputError(
        file, "unsupported mesh format '" + ext + "' (expected .glb, .gltf, .obj, .ply or .off)");
  }
  requireRegularFile(file, "mesh file");
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  if (bytes == 0) throw InputError(file, "mesh file is empty");
  if (bytes > inputLimits().maxFileBytes())
    throw InputError(file, fileLimitProblem("mesh file", bytes));
}

std::string describeVertex(const aiVector3D& v) {
  std::ostringstream s;
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

// Assimp strips the mesh format's own validation down to "it parsed"; we still refuse what
// would poison every ray: non-finite coordinates and faces pointing at missing vertices.
void appendAssimpMesh(const aiMesh& mesh, const aiMatrix4x4& fileFromMesh, const std::string& name,
                      const std::filesystem::path& file, UpAxis fileUp, double metersPerUnit,
                      LevelMesh& out) {
  LevelPart part;
  part.name = name;
  part.file = file;
  part.firstTriangle = static_cast<std::uint32_t>(out.triangles.size());

  const auto base = static_cast<std::uint32_t>(out.positionsMeters.size());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D v = fileFromMesh * mesh.mVertices[i];
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

// Node transforms are applied here rather than by Assimp's PreTransformVertices, which would
// merge every mesh that shares a material and lose the object names artists look for.
void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& fileFromParent,
                const std::filesystem::path& file, UpAxis fileUp, double metersPerUnit,
                LevelMesh& out) {
  const aiMatrix4x4 fileFromNode = fileFromParent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    // Artists look for the object's name (the node); the mesh data's name is a fallback.
    std::string name =
        node.mName.length > 0 && &node != scene.mRootNode ? node.mName.C_Str() : mesh.mName.C_Str();
    if (name.empty()) name = "mesh" + std::to_string(out.parts.size());
    appendAssimpMesh(mesh, fileFromNode, name, file, fileUp, metersPerUnit, out);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    appendNode(scene, *node.mChildren[c], fileFromNode, file, fileUp, metersPerUnit, out);
  }
}

// Assimp repairs some broken files quietly (an OFF face index past the end is clamped, an OBJ
// number that does not parse becomes 0) and only says so in its error log. A level built
// from a repaired file would be wrong without anyone knowing, so the first logged error
// rejects the file. Assimp's logger is global: loads take turns.
class AssimpErrorLog : public Assimp::LogStream {
 public:
  AssimpErrorLog() {
    Assimp::DefaultLogger::create(nullptr, Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(this, Assimp::Logger::Err);
  }
  ~AssimpErrorLog() override {
    Assimp::DefaultLogger::get()->detachStream(this, Assimp::Logger::Err);
    Assimp::DefaultLogger::kill();
  }
  void write(const char* message) override {
    if (first_.empty()) first_ = message;
  }
  // Without Assimp's "Error, T0: " prefix and trailing newline.
  std::string firstError() const {
    std::string m = first_;
    if (const auto colon = m.find(": "); m.rfind("Error", 0) == 0 && colon != std::string::npos) {
      m = m.substr(colon + 2);
    }
    while (!m.empty() && (m.back() == '\n' || m.back() == '\r')) m.pop_back();
    return m;
  }

 private:
  std::string first_;
};

std::mutex assimpMutex;

// Assimp picks its importer by extension, but when that importer's signature check refuses
// the file it tries every other importer on the content: a broken .gltf was then read as
// OpenGEX, whose parser reads past its buffer (found by fuzz_level_gltf; Assimp 5.2.5). A
// level file is read only as the format its extension names, or refused.
void requireExtensionImporterAccepts(Assimp::Importer& importer,
                                     const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file).substr(1);
  for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
    std::istringstream extensions(importer.GetImporterInfo(i)->mFileExtensions);
    for (std::string e; extensions >> e;) {
      if (e == ext &&
          importer.GetImporter(i)->CanRead(file.string(), importer.GetIOHandler(), true))
        return;
    }
  }
  throw InputError(file,
                   "malformed mesh: not a ." + ext + " file (its content does not start as one)");
}

void requireTrianglesWithinLimit(const std::filesystem::path& source, const LevelMesh& mesh) {
  const std::size_t triangles = mesh.triangles.size() + mesh.skyTriangles.size();
  if (triangles > inputLimits().maxTriangles)
    throw InputError(source, triangleLimitProblem(triangles));
}

}  // namespace

// Every reader converts to float metres; a coordinate past the scene limit (or one that
// overflowed float on the way) would reach Embree, so it stops here, whatever the format.
void requireLevelWithinLimits(const std::filesystem::path& source, const LevelMesh& mesh) {
  requireTrianglesWithinLimit(source, mesh);
  for (std::size_t i = 0; i < mesh.positionsMeters.size(); ++i) {
    const glm::vec3 p = mesh.positionsMeters[i];
    if (std::abs(p.x) <= kMaxSceneMeters && std::abs(p.y) <= kMaxSceneMeters &&
        std::abs(p.z) <= kMaxSceneMeters)
      continue;
    std::ostringstream problem;
    problem << "vertex " << i << " is at (" << p.x << ", " << p.y << ", " << p.z
            << ") m, expected coordinates within " << kMaxSceneMeters
            << " m (the limit of a scene, in metres)";
    throw InputError(source, problem.str());
  }
}

LevelMesh loadLevelMeshFile(const std::filesystem::path& file, UpAxis fileUp,
                            double metersPerUnit) {
  requireReadableMeshFile(file);
  if (isPolygonSoupFile(file)) {
    LevelMesh level = readPolygonSoupFile(file, fileUp, metersPerUnit);
    requireLevelWithinLimits(file, level);
    return level;
  }

  const std::lock_guard<std::mutex> lock(assimpMutex);
  AssimpErrorLog errors;
  // Before any Assimp code reads the file: its glTF importer's signature check already takes
  // a GLB chunk's length as given.
  const std::string ext = lowerExtension(file);
  const bool gltf = ext == ".gltf" || ext == ".glb";
  const GltfClaims claims = gltf ? gltfClaims(file) : GltfClaims{};
  if (ext == ".obj") requireReadableMaterialLibraries(file);
  if (!claims.problem.empty()) throw InputError(file, "malformed mesh: " + claims.problem);
  Assimp::Importer importer;
  requireExtensionImporterAccepts(importer, file);
  // Polygons are triangulated; nothing is welded, fixed or removed, so what we measure is the
  // level as authored. Points and lines are skipped below: they carry no surface.
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate);
  if (scene == nullptr) {
    std::string reason = importer.GetErrorString();
    if (reason.empty()) reason = errors.firstError();
    if (reason.empty()) reason = "not a readable mesh";
    throw InputError(file, "malformed mesh: " + reason);
  }
  if (!errors.firstError().empty())
    throw InputError(file, "malformed mesh: " + errors.firstError());
  if (gltf) {
    std::vector<std::size_t> trianglesRead;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
      const aiMesh& mesh = *scene->mMeshes[m];
      trianglesRead.push_back(
          std::size_t(std::count_if(mesh.mFaces, mesh.mFaces + mesh.mNumFaces,
                                    [](const aiFace& f) { return f.mNumIndices == 3; })));
    }
    const std::string lost = gltfTrianglesLostProblem(claims, trianglesRead);
    if (!lost.empty()) throw InputError(file, "malformed mesh: " + lost);
  }

  LevelMesh level;
  if (scene->mRootNode != nullptr) {
    appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), file, fileUp, metersPerUnit, level);
  }
  if (level.triangles.empty()) throw InputError(file, "mesh has no triangles");
  requireLevelWithinLimits(file, level);
  return level;
}

LevelMesh loadLevelMeshRef(const LevelMeshRef& ref, double sceneMetersPerUnit) {
  const std::string ext = lowerExtension(ref.path);
  if (ext != ".bsp" && ext != ".pk3") {
    return loadLevelMeshFile(ref.path, ref.up, sceneMetersPerUnit);
  }
  BspLevel bsp = readBspLevel(ref.path, ref.map);
  if (bsp.mesh.triangles.empty()) {
    const std::filesystem::path named =
        ref.map.empty() ? ref.path
                        : std::filesystem::path(ref.path.string() + ":" + ref.map.generic_string());
    throw InputError(named, "BSP has no solid faces");
  }
  requireLevelWithinLimits(ref.path, bsp.mesh);
  for (const BspSpawnPoint& s : bsp.spawnPoints)
    bsp.mesh.spawnPointsMeters.push_back(s.originMeters);
  return std::move(bsp.mesh);
}

LevelMesh loadLevel(const Scene& scene) {
  if (scene.level.empty()) throw InputError(scene.file, "the level lists no meshes");
  LevelMesh level;
  for (const LevelMeshRef& ref : scene.level) {
    appendLevelMesh(level, loadLevelMeshRef(ref, scene.metersPerUnit));
    // Each mesh's vertices were checked as it was read; the count is checked as the meshes add
    // up, so that many within the limit cannot pass it (or the 32-bit indices) together.
    requireTrianglesWithinLimit(scene.file, level);
  }
  return level;
}

}  // namespace probeproxy
