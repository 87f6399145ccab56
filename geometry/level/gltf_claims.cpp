#include "geometry/level/gltf_claims.h"

#include "core/scene/scene_limits.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>

namespace probeproxy {

namespace {

using nlohmann::json;

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

// A .glb's header and chunks must fit in the file: Assimp takes each chunk's length as given
// and asks for that much memory first (found by fuzz_level_glb: a 40-byte file whose JSON
// chunk claims 4 GB). Only the chunk headers and the JSON chunk are read, not the binary
// buffer. Empty when they fit, with `json` the JSON chunk.
std::string glbChunkProblem(std::ifstream& in, std::uint64_t size, std::string& text,
                            bool& binaryChunk) {
  if (size < 20) return {};  // too short for a chunk: Assimp says so
  const std::uint32_t claimed = u32(readAt(in, 0, 12), 8);
  if (claimed != size) {
    return "GLB header claims " + std::to_string(claimed) + " bytes, the file holds " +
           std::to_string(size);
  }
  std::uint64_t at = 12;
  for (int chunk = 0; at + 8 <= size; ++chunk) {
    const std::string header = readAt(in, at, 8);
    if (header.size() < 8) return {};
    const std::uint32_t length = u32(header, 0), type = u32(header, 4);
    if (length > size - at - 8) {
      return "GLB chunk " + std::to_string(chunk) + " claims " + std::to_string(length) +
             " bytes, past the end of the file's " + std::to_string(size);
    }
    if (chunk == 0 && type == 0x4E4F534Au) text = readAt(in, at + 8, length);  // "JSON"
    if (chunk == 1 && type == 0x004E4942u) binaryChunk = true;                 // "BIN"
    at += 8 + std::uint64_t(length);
  }
  return {};
}

// A member that must be a non-negative integer: its value, `absent` when it is missing, nullopt
// when it is anything else (a float, a negative number, a string).
std::optional<std::uint64_t> natural(const json& object, const char* key,
                                     std::optional<std::uint64_t> absent = std::nullopt) {
  if (!object.contains(key)) return absent;
  const json& v = object[key];
  if (v.is_number_unsigned()) return v.get<std::uint64_t>();
  if (v.is_number_integer() && v.get<std::int64_t>() >= 0)
    return std::uint64_t(v.get<std::int64_t>());
  return std::nullopt;
}

std::string describe(const json& value) { return value.dump().substr(0, 40); }

const json& arrayMember(const json& gltf, const char* key) {
  static const json empty = json::array();
  return gltf.contains(key) && gltf[key].is_array() ? gltf[key] : empty;
}

// Which problem a member has, e.g. "glTF accessor 0 byteOffset is -4, expected a non-negative
// integer".
std::string badMember(const std::string& owner, const char* key, const json& object,
                      const std::string& expected) {
  return owner + " " + key + " is " + (object.contains(key) ? describe(object[key]) : "missing") +
         ", expected " + expected;
}

std::size_t componentBytes(std::uint64_t componentType) {
  switch (componentType) {
    case 5120:  // BYTE
    case 5121:  // UNSIGNED_BYTE
      return 1;
    case 5122:  // SHORT
    case 5123:  // UNSIGNED_SHORT
      return 2;
    case 5125:  // UNSIGNED_INT
    case 5126:  // FLOAT
      return 4;
    default:
      return 0;
  }
}

std::size_t componentsOf(const std::string& type) {
  static const std::pair<const char*, std::size_t> kTypes[] = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
  for (const auto& [name, count] : kTypes)
    if (type == name) return count;
  return 0;
}

// A .gltf's buffer may be a file beside it; reading a FIFO or a folder there would block or
// fail deep in Assimp.
std::string bufferUriProblem(const std::filesystem::path& file, std::size_t index,
                             const std::string& uri) {
  if (uri.rfind("data:", 0) == 0) return {};
  const std::filesystem::path target = file.parent_path() / uri;
  std::error_code ec;
  const std::string owner = "glTF buffer " + std::to_string(index) + " file '" + uri + "'";
  if (!std::filesystem::exists(target, ec)) return owner + " is not found";
  if (!std::filesystem::is_regular_file(target, ec)) return owner + " is not a regular file";
  return {};
}

// Buffers, buffer views and accessors: every offset, length and count a non-negative integer
// and every view inside its buffer, every accessor inside its view.
std::string bufferProblem(const std::filesystem::path& file, const json& gltf) {
  const json& buffers = arrayMember(gltf, "buffers");
  const json& views = arrayMember(gltf, "bufferViews");
  const json& accessors = arrayMember(gltf, "accessors");
  double declared = 0.0;
  std::vector<std::uint64_t> bufferBytes;
  for (std::size_t b = 0; b < buffers.size(); ++b) {
    const std::string owner = "glTF buffer " + std::to_string(b);
    if (!buffers[b].is_object()) return owner + " is not an object";
    const auto length = natural(buffers[b], "byteLength");
    if (!length) return badMember(owner, "byteLength", buffers[b], "a non-negative integer");
    bufferBytes.push_back(*length);
    declared += double(*length);
  }
  // Buffers may live in files beside it, which the mesh file's own size does not count.
  if (declared > double(inputLimits().maxFileBytes()))
    return fileLimitProblem("its buffers' declared byteLength",
                            std::uint64_t(std::min(declared, 1e18)));
  for (std::size_t b = 0; b < buffers.size(); ++b) {
    if (!buffers[b].contains("uri") || !buffers[b]["uri"].is_string()) continue;
    if (std::string p = bufferUriProblem(file, b, buffers[b]["uri"].get<std::string>()); !p.empty())
      return p;
  }
  std::vector<std::uint64_t> viewBytes;
  for (std::size_t v = 0; v < views.size(); ++v) {
    const std::string owner = "glTF bufferView " + std::to_string(v);
    const json& view = views[v];
    if (!view.is_object()) return owner + " is not an object";
    const auto buffer = natural(view, "buffer");
    if (!buffer || *buffer >= bufferBytes.size())
      return badMember(owner, "buffer", view, "one of its " + std::to_string(bufferBytes.size()));
    const auto offset = natural(view, "byteOffset", 0);
    if (!offset) return badMember(owner, "byteOffset", view, "a non-negative integer");
    const auto length = natural(view, "byteLength");
    if (!length) return badMember(owner, "byteLength", view, "a non-negative integer");
    const auto stride = natural(view, "byteStride", 4);
    if (!stride || *stride < 4 || *stride > 252 || *stride % 4 != 0)
      return badMember(owner, "byteStride", view, "a multiple of 4 from 4 to 252");
    if (*offset > bufferBytes[*buffer] || *length > bufferBytes[*buffer] - *offset) {
      return owner + " (bytes " + std::to_string(*offset) + " to " +
             std::to_string(*offset + *length) + ") runs past buffer " + std::to_string(*buffer) +
             "'s " + std::to_string(bufferBytes[*buffer]) + " bytes";
    }
    viewBytes.push_back(*length);
  }
  for (std::size_t a = 0; a < accessors.size(); ++a) {
    const std::string owner = "glTF accessor " + std::to_string(a);
    const json& accessor = accessors[a];
    if (!accessor.is_object()) return owner + " is not an object";
    const auto componentType = natural(accessor, "componentType");
    const std::size_t component = componentType ? componentBytes(*componentType) : 0;
    if (component == 0)
      return badMember(owner, "componentType", accessor, "5120, 5121, 5122, 5123, 5125 or 5126");
    const std::size_t components = accessor.contains("type") && accessor["type"].is_string()
                                       ? componentsOf(accessor["type"].get<std::string>())
                                       : 0;
    if (components == 0)
      return badMember(owner, "type", accessor, "SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
    const auto count = natural(accessor, "count");
    if (!count || *count == 0) return badMember(owner, "count", accessor, "a positive integer");
    const auto offset = natural(accessor, "byteOffset", 0);
    if (!offset) return badMember(owner, "byteOffset", accessor, "a non-negative integer");
    if (!accessor.contains("bufferView")) continue;  // all zeros, as the spec says
    const auto view = natural(accessor, "bufferView");
    if (!view || *view >= viewBytes.size())
      return badMember(owner, "bufferView", accessor,
                       "one of the " + std::to_string(viewBytes.size()) + " buffer views");
    const std::uint64_t element = component * components;
    const std::uint64_t stride = natural(views[*view], "byteStride", element).value_or(element);
    // Counts are at most 2^64 / stride only in theory; a double keeps the product honest.
    const double end = double(*offset) + double(stride) * double(*count - 1) + double(element);
    if (end > double(viewBytes[*view])) {
      return owner + " (" + std::to_string(*count) + " elements from byte " +
             std::to_string(*offset) + ") runs past bufferView " + std::to_string(*view) + "'s " +
             std::to_string(viewBytes[*view]) + " bytes";
    }
  }
  return {};
}

// Every node at most one parent's child, and the hierarchy at most kMaxGltfNodeDepth deep.
// The walk is iterative and visits each node once, so a hostile graph cannot make it deep or
// long.
std::string nodeProblem(const json& gltf) {
  const json& nodes = arrayMember(gltf, "nodes");
  std::vector<int> parents(nodes.size(), 0);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (!nodes[n].is_object() || !nodes[n].contains("children")) continue;
    const json& children = nodes[n]["children"];
    if (!children.is_array()) return "glTF node " + std::to_string(n) + " children is not an array";
    for (const json& child : children) {
      const std::optional<std::uint64_t> c =
          child.is_number_unsigned() ? std::optional<std::uint64_t>(child.get<std::uint64_t>())
                                     : std::nullopt;
      if (!c || *c >= nodes.size()) {
        return "glTF node " + std::to_string(n) + " has child " + describe(child) +
               ", expected one of its " + std::to_string(nodes.size()) + " nodes";
      }
      if (++parents[*c] > 1)
        return "glTF node " + std::to_string(*c) + " is the child of two nodes (or of itself)";
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> stack;  // node, depth
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (parents[n] == 0) stack.emplace_back(n, 1);
  while (!stack.empty()) {
    const auto [n, depth] = stack.back();
    stack.pop_back();
    if (depth > kMaxGltfNodeDepth) {
      return "glTF node hierarchy is deeper than " + std::to_string(kMaxGltfNodeDepth) +
             " nodes (node " + std::to_string(n) + ")";
    }
    if (!nodes[n].is_object() || !nodes[n].contains("children")) continue;
    for (const json& child : nodes[n]["children"])
      stack.emplace_back(child.get<std::size_t>(), depth + 1);
  }
  return {};
}

// Each primitive: positions as three floats, indices as unsigned integers, a mode Assimp reads
// safely. Appends the triangles it claims.
std::string primitiveProblem(const json& primitive, const std::string& owner, const json& gltf,
                             std::size_t& triangles) {
  const json& accessors = arrayMember(gltf, "accessors");
  const bool positioned = primitive.is_object() && primitive.contains("attributes") &&
                          primitive["attributes"].is_object() &&
                          primitive["attributes"].contains("POSITION");
  if (!positioned) return owner + " has no POSITION attribute";
  const auto mode = natural(primitive, "mode", 4);
  if (!mode || *mode > 6) return badMember(owner, "mode", primitive, "an integer from 0 to 6");
  if (*mode == 2) {
    return owner +
           " is a line loop (mode 2), which Assimp 5.2 cannot read safely; a level's lines "
           "carry no surface: remove it";
  }
  const auto position = natural(primitive["attributes"], "POSITION");
  if (!position || *position >= accessors.size())
    return owner + " POSITION is " + describe(primitive["attributes"]["POSITION"]) +
           ", expected one of the " + std::to_string(accessors.size()) + " accessors";
  const json& positions = accessors[*position];
  if (positions["type"] != "VEC3" || positions["componentType"] != 5126) {
    return owner + " POSITION (accessor " + std::to_string(*position) + ") is " +
           describe(positions["type"]) + " of component type " +
           describe(positions["componentType"]) + ", expected VEC3 of 5126 (float)";
  }
  std::uint64_t corners = positions["count"].get<std::uint64_t>();
  if (primitive.contains("indices")) {
    const auto indices = natural(primitive, "indices");
    if (!indices || *indices >= accessors.size())
      return badMember(owner, "indices", primitive,
                       "one of the " + std::to_string(accessors.size()) + " accessors");
    const json& index = accessors[*indices];
    const bool unsignedType = index["componentType"] == 5121 || index["componentType"] == 5123 ||
                              index["componentType"] == 5125;
    if (index["type"] != "SCALAR" || !unsignedType) {
      return owner + " indices (accessor " + std::to_string(*indices) + ") are " +
             describe(index["type"]) + " of component type " + describe(index["componentType"]) +
             ", expected SCALAR of 5121, 5123 or 5125";
    }
    corners = index["count"].get<std::uint64_t>();
  }
  triangles = *mode == 4 ? corners / 3 : *mode >= 5 && corners >= 3 ? corners - 2 : 0;
  return {};
}

}  // namespace

GltfClaims gltfClaims(const std::filesystem::path& file) {
  GltfClaims claims;
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(file, ec);
  if (ec) return claims;
  std::ifstream in(file, std::ios::binary);
  std::string text;
  bool binaryChunk = false;
  if (readAt(in, 0, 4) == "glTF") {
    claims.problem = glbChunkProblem(in, size, text, binaryChunk);
    if (!claims.problem.empty()) return claims;
  } else {
    text = readAt(in, 0, size);
  }
  // Assimp's JSON parser takes strings that are not UTF-8; nlohmann's refuses them. Every
  // JSON token outside a string is ASCII, so bytes past it only ever stand in a string.
  for (char& c : text)
    if (static_cast<unsigned char>(c) >= 0x80) c = '?';
  const json gltf = json::parse(text, nullptr, false);
  if (!gltf.is_object()) return claims;
  const auto fail = [&](std::string problem) {
    claims.problem = std::move(problem);
    claims.primitiveTriangles.clear();
    return claims;
  };
  // glTF 1.0 files go to another Assimp importer with rules of their own; a file without an
  // asset does not say which it is, and Assimp guesses.
  if (!gltf.contains("asset") || !gltf["asset"].is_object() || !gltf["asset"].contains("version") ||
      !gltf["asset"]["version"].is_string())
    return fail("glTF has no \"asset\" naming its version (glTF 2.0 requires one)");
  if (gltf["asset"]["version"].get<std::string>().rfind("2.", 0) != 0) return claims;
  if (std::string p = bufferProblem(file, gltf); !p.empty()) return fail(p);
  // The spec reads a buffer with a uri from that uri; Assimp reads buffer 0 of a GLB from its
  // BIN chunk whatever it says. The two may differ, so the file says two things.
  if (binaryChunk && arrayMember(gltf, "buffers").size() > 0 &&
      gltf["buffers"][0].contains("uri")) {
    return fail(
        "GLB buffer 0 has a uri and the file a BIN chunk: glTF 2.0 reads the uri, Assimp the "
        "chunk; remove one");
  }
  if (std::string p = nodeProblem(gltf); !p.empty()) return fail(p);
  const json& meshes = arrayMember(gltf, "meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    if (!meshes[m].is_object()) return fail("glTF mesh " + std::to_string(m) + " is not an object");
    const json& primitives = arrayMember(meshes[m], "primitives");
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      std::size_t triangles = 0;
      const std::string owner =
          "glTF mesh " + std::to_string(m) + " primitive " + std::to_string(p);
      if (std::string problem = primitiveProblem(primitives[p], owner, gltf, triangles);
          !problem.empty())
        return fail(problem);
      claims.primitiveTriangles.push_back(triangles);
      claims.primitiveNames.push_back(owner);
    }
  }
  return claims;
}

std::string gltfTrianglesLostProblem(const GltfClaims& claims,
                                     const std::vector<std::size_t>& trianglesRead) {
  if (claims.primitiveTriangles.size() != trianglesRead.size()) return {};
  for (std::size_t i = 0; i < trianglesRead.size(); ++i) {
    if (trianglesRead[i] >= claims.primitiveTriangles[i]) continue;
    return claims.primitiveNames[i] + ": " +
           std::to_string(claims.primitiveTriangles[i] - trianglesRead[i]) + " of its " +
           std::to_string(claims.primitiveTriangles[i]) +
           " triangles name a vertex past its POSITION count";
  }
  return {};
}

}  // namespace probeproxy
