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

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;  // GLB is little-endian, as every machine this builds for
}

// A .glb's chunks must fit in the file: Assimp takes each chunk's length as given and asks for
// that much memory first (found by fuzz_level_glb: a 40-byte file whose JSON chunk claims 4 GB).
// Empty when they fit, with `json` the JSON chunk.
std::string glbChunkProblem(const std::string& bytes, std::string& json) {
  if (bytes.size() < 20) return {};  // too short for a chunk: Assimp says so
  std::size_t at = 12;
  for (int chunk = 0; at + 8 <= bytes.size(); ++chunk) {
    const std::uint32_t length = u32(bytes, at), type = u32(bytes, at + 4);
    if (length > bytes.size() - at - 8) {
      return "GLB chunk " + std::to_string(chunk) + " claims " + std::to_string(length) +
             " bytes, past the end of the file's " + std::to_string(bytes.size());
    }
    if (chunk == 0 && type == 0x4E4F534Au) json = bytes.substr(at + 8, length);  // "JSON"
    at += 8 + std::size_t(length);
  }
  return {};
}

}  // namespace

std::string gltfClaimProblem(const std::filesystem::path& file) {
  // Assimp's JSON parser takes strings that are not UTF-8; nlohmann's refuses them. Every
  // JSON token outside a string is ASCII, so bytes past it only ever stand in a string.
  std::ifstream in(file, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  std::string text = bytes;
  if (bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0) {
    text.clear();
    const std::string chunks = glbChunkProblem(bytes, text);
    if (!chunks.empty()) return chunks;
  }
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

