#include "geometry/level/gltf_claims.h"

#include "core/scene/scene_limits.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace probeproxy {

namespace {

// The JSON of a .gltf, or of a .glb's first chunk; empty when the container is malformed.
std::string gltfJson(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  if (bytes.size() < 4 || bytes.compare(0, 4, "glTF") != 0) return bytes;
  std::uint32_t length = 0, type = 0;
  if (bytes.size() < 20) return {};
  std::memcpy(&length, bytes.data() + 12, 4);
  std::memcpy(&type, bytes.data() + 16, 4);
  if (type != 0x4E4F534Au || length > bytes.size() - 20) return {};  // "JSON"
  return bytes.substr(20, length);
}

}  // namespace

std::string gltfClaimProblem(const std::filesystem::path& file) {
  // Assimp's JSON parser takes strings that are not UTF-8; nlohmann's refuses them. Every
  // JSON token outside a string is ASCII, so bytes past it only ever stand in a string.
  std::string text = gltfJson(file);
  for (char& c : text)
    if (static_cast<unsigned char>(c) >= 0x80) c = '?';
  const nlohmann::json gltf = nlohmann::json::parse(text, nullptr, false);
  if (!gltf.is_object()) return {};
  // Buffers may live in files beside it, which the mesh file's own size does not count.
  if (gltf.contains("buffers") && gltf["buffers"].is_array()) {
    double declared = 0.0;
    for (const nlohmann::json& buffer : gltf["buffers"])
      if (buffer.is_object() && buffer.contains("byteLength") && buffer["byteLength"].is_number())
        declared += buffer["byteLength"].get<double>();
    if (declared > double(inputLimits().maxFileBytes))
      return fileLimitProblem("its buffers' declared byteLength", std::uint64_t(std::min(declared, 1e18)));
  }
  if (!gltf.contains("meshes") || !gltf["meshes"].is_array()) return {};
  const nlohmann::json& meshes = gltf["meshes"];
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    if (!meshes[m].is_object() || !meshes[m].contains("primitives") ||
        !meshes[m]["primitives"].is_array())
      continue;
    const nlohmann::json& primitives = meshes[m]["primitives"];
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const nlohmann::json& primitive = primitives[p];
      const bool positioned = primitive.is_object() && primitive.contains("attributes") &&
                              primitive["attributes"].is_object() &&
                              primitive["attributes"].contains("POSITION");
      const std::string where = "glTF mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      if (!positioned) return where + " has no POSITION attribute";
      if (primitive.contains("mode") && primitive["mode"] == 2) {
        return where + " is a line loop (mode 2), which Assimp 5.2 cannot read safely; a level's "
                       "lines carry no surface: remove it";
      }
    }
  }
  return {};
}

}  // namespace probeproxy
