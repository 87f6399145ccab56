#include "geometry/level/gltf_claims.h"

#include "core/scene/scene_limits.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>

namespace probeproxy {

namespace {

// The bytes of `in` from `at`, `count` of them (fewer at the end of the file).
std::string readAt(std::ifstream& in, std::uint64_t at, std::uint64_t count) {
  std::string bytes(count, '\0');
  in.clear();
  in.seekg(std::streamoff(at));
  in.read(bytes.data(), std::streamsize(count));
  bytes.resize(std::size_t(std::max<std::streamsize>(in.gcount(), 0)));
  return bytes;
}

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;  // GLB is little-endian, as every machine this builds for
}

// A .glb's chunks must fit in the file: Assimp takes each chunk's length as given and asks for
// that much memory first (found by fuzz_level_glb: a 40-byte file whose JSON chunk claims 4 GB).
// Only the chunk headers and the JSON chunk are read, not the binary buffer. Empty when they
// fit, with `json` the JSON chunk.
std::string glbChunkProblem(std::ifstream& in, std::uint64_t size, std::string& json) {
  if (size < 20) return {};  // too short for a chunk: Assimp says so
  std::uint64_t at = 12;
  for (int chunk = 0; at + 8 <= size; ++chunk) {
    const std::string header = readAt(in, at, 8);
    if (header.size() < 8) return {};
    const std::uint32_t length = u32(header, 0), type = u32(header, 4);
    if (length > size - at - 8) {
      return "GLB chunk " + std::to_string(chunk) + " claims " + std::to_string(length) +
             " bytes, past the end of the file's " + std::to_string(size);
    }
    if (chunk == 0 && type == 0x4E4F534Au) json = readAt(in, at + 8, length);  // "JSON"
    at += 8 + std::uint64_t(length);
  }
  return {};
}

}  // namespace

std::string gltfClaimProblem(const std::filesystem::path& file) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(file, ec);
  if (ec) return {};
  std::ifstream in(file, std::ios::binary);
  std::string text;
  if (readAt(in, 0, 4) == "glTF") {
    const std::string chunks = glbChunkProblem(in, size, text);
    if (!chunks.empty()) return chunks;
  } else {
    text = readAt(in, 0, size);
  }
  // Assimp's JSON parser takes strings that are not UTF-8; nlohmann's refuses them. Every
  // JSON token outside a string is ASCII, so bytes past it only ever stand in a string.
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
    if (declared > double(inputLimits().maxFileBytes()))
      return fileLimitProblem("its buffers' declared byteLength",
                              std::uint64_t(std::min(declared, 1e18)));
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
      const std::string where =
          "glTF mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      if (!positioned) return where + " has no POSITION attribute";
      if (primitive.contains("mode") && primitive["mode"] == 2) {
        return where +
               " is a line loop (mode 2), which Assimp 5.2 cannot read safely; a level's "
               "lines carry no surface: remove it";
      }
    }
  }
  return {};
}

}  // namespace probeproxy
