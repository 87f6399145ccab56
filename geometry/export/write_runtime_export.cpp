#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/write_level_mesh.h"

#include <nlohmann/json.hpp>

#include <unistd.h>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <system_error>

namespace probeproxy {

namespace {

namespace fs = std::filesystem;

const char kExportElsewhere[] = "; refusing to overwrite it (export to another folder)";
const char kMoveIt[] = "; refusing to overwrite it (move it away or export to another folder)";

fs::path comparable(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return path.lexically_normal();
  const fs::path canonical = fs::weakly_canonical(absolute, ec);  // resolves symlinks
  return ec ? absolute.lexically_normal() : canonical;
}

// An output path must not be a file the scene names: the scene file, its level, an authored
// proxy mesh.
void refuseAuthoredTargets(const Scene& scene, const fs::path& output) {
  const fs::path target = comparable(output);
  if (!scene.file.empty() && comparable(scene.file) == target) {
    throw InputError(output, std::string("is the scene file") + kExportElsewhere);
  }
  for (const LevelMeshRef& mesh : scene.level) {
    if (comparable(mesh.path) == target) {
      throw InputError(output, std::string("is a level mesh of the scene") + kExportElsewhere);
    }
  }
  for (const Probe& probe : scene.probes) {
    const auto* convex = std::get_if<AuthoredConvexMesh>(&probe.proxy);
    if (convex && comparable(convex->mesh) == target) {
      throw InputError(
          output, "is the authored proxy mesh of probe '" + probe.name + "'" + kExportElsewhere);
    }
  }
}

bool isOurProxiesJson(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return false;
  const nlohmann::json root = nlohmann::json::parse(bytes, nullptr, /*allow_exceptions=*/false);
  return root.is_object() && root.contains(kRuntimeExportFormatId);
}

// A proxies.json that is not ours, or a proxies.glb with no proxies.json of ours beside it,
// was made by someone else.
void refuseForeignOutputs(const fs::path& json, const fs::path& glb) {
  std::error_code ec;
  const bool jsonExists = fs::exists(json, ec);
  for (const fs::path& output : {json, glb}) {
    if (fs::exists(output, ec) && !fs::is_regular_file(output, ec))
      throw InputError(output, std::string("exists and is not a file") + kMoveIt);
  }
  if (jsonExists && !isOurProxiesJson(json)) {
    throw InputError(json, std::string("exists and is not a probeproxy runtime export (no \"") +
                               kRuntimeExportFormatId + "\" member)" + kMoveIt);
  }
  if (!jsonExists && fs::exists(glb, ec)) {
    throw InputError(glb, std::string("exists without a probeproxy ") + kProxiesJsonName +
                              " beside it" + kMoveIt);
  }
}

void putU32(std::string& bytes, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}

// A valid glTF 2.0 binary with an empty scene: the export when no probe has a volume
// (Assimp will not write a scene without meshes).
std::string emptyGlb() {
  std::string json =
      R"({"asset":{"version":"2.0","generator":"probeproxy"},"scene":0,"scenes":[{"nodes":[]}]})";
  while (json.size() % 4 != 0) json += ' ';
  std::string bytes = "glTF";
  putU32(bytes, 2);
  putU32(bytes, static_cast<std::uint32_t>(12 + 8 + json.size()));
  putU32(bytes, static_cast<std::uint32_t>(json.size()));
  bytes += "JSON";
  bytes += json;
  return bytes;
}

fs::path stagedBeside(const fs::path& target) {
  std::string name = ".";  // built in place: GCC 12 warns (-Wrestrict) on chained operator+
  name += target.stem().string();
  name += ".staged";
  name += std::to_string(::getpid());
  name += target.extension().string();
  return target.parent_path() / name;
}

void removeQuietly(const fs::path& file) {
  std::error_code ignored;
  fs::remove(file, ignored);
}

void renameOrThrow(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) throw InputError(to, "cannot write: " + ec.message());
}

}  // namespace

void writeRuntimeExport(const Scene& scene, const std::vector<ProbeProxyBuild>& builds,
                        const std::filesystem::path& outFolder) {
  writeRuntimeExport(scene, makeRuntimeExport(scene, builds), outFolder);
}

void writeRuntimeExport(const Scene& scene, const RuntimeExport& runtime,
                        const std::filesystem::path& outFolder) {
  const std::string json = runtimeExportJson(runtime);
  const LevelMesh mesh = runtimeExportMesh(runtime);

  const fs::path jsonPath = outFolder / kProxiesJsonName;
  const fs::path glbPath = outFolder / kProxiesGlbName;
  refuseAuthoredTargets(scene, jsonPath);
  refuseAuthoredTargets(scene, glbPath);
  refuseForeignOutputs(jsonPath, glbPath);

  // Both files complete beside their targets first, then renamed: a failure on the way
  // leaves the previous export (or nothing) in place, never a partial file.
  const fs::path stagedGlb = stagedBeside(glbPath);
  const fs::path stagedJson = stagedBeside(jsonPath);
  try {
    if (mesh.triangles.empty()) {
      writeFileAtomically(stagedGlb, emptyGlb());
    } else {
      writeLevelMeshFile(mesh, stagedGlb, UpAxis::Y);  // glTF is Y up, metres
    }
    writeFileAtomically(stagedJson, json);
    renameOrThrow(stagedGlb, glbPath);
    renameOrThrow(stagedJson, jsonPath);  // last: a loader reads proxies.json first
  } catch (...) {
    removeQuietly(stagedGlb);
    removeQuietly(stagedJson);
    throw;
  }
}

}  // namespace probeproxy
