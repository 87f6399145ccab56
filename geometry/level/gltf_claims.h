#pragma once
// What a glTF or GLB file must hold before Assimp reads it. Debian's Assimp 5.2.5 trusts it:
// a line loop (mode 2) whose indices or positions are not what they claim makes its glTF2
// importer read through a null pointer (found by fuzz_level_glb); a node hierarchy thousands
// deep overflows the stack of its importer and ours; an accessor at a negative offset or a
// POSITION that is not three floats is read as garbage geometry; an index past the vertex
// count drops its triangle without a word. So the file's JSON is checked first, against the
// glTF 2.0 rules that bear on geometry, and the triangle count each primitive claims is kept
// to compare with what Assimp read.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace probeproxy {

// The deepest node hierarchy a level may hold. Real levels nest tens of nodes; the importers
// recurse once per level.
inline constexpr std::size_t kMaxGltfNodeDepth = 256;

struct GltfClaims {
  // Empty when the JSON holds what probeproxy reads, or does not parse (Assimp then says what
  // is wrong); otherwise the problem, e.g. "glTF mesh 0 primitive 0 has no POSITION attribute".
  std::string problem;
  // Triangles each mesh primitive claims, in the order Assimp turns primitives into meshes
  // (mesh by mesh, primitive by primitive); empty when the file is not glTF 2.0 JSON.
  std::vector<std::size_t> primitiveTriangles;
  std::vector<std::string> primitiveNames;  // "glTF mesh 0 primitive 1", beside each count
};

GltfClaims gltfClaims(const std::filesystem::path& file);

// Empty when Assimp's meshes hold the triangles the primitives claim; otherwise which
// primitive lost triangles (Assimp drops a triangle with an index past the vertex count and
// only logs a warning).
std::string gltfTrianglesLostProblem(const GltfClaims& claims,
                                     const std::vector<std::size_t>& trianglesRead);

}  // namespace probeproxy
