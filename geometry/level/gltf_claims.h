#pragma once
// What a glTF or GLB file must hold before Assimp reads it. Debian's Assimp 5.2.5 trusts it:
// a primitive with no POSITION attribute drawn as lines with indices makes its glTF2 importer
// read through a null pointer (found by fuzz_level_glb). probeproxy reads triangles, and a
// primitive without positions has none, so such a file is refused first, naming the primitive.

#include <filesystem>
#include <string>

namespace probeproxy {

// Empty when every mesh primitive of the file's JSON (the .gltf, or a .glb's JSON chunk) has a
// POSITION attribute, or when the JSON does not parse (Assimp then says what is wrong);
// otherwise the problem, e.g. "glTF mesh 0 primitive 0 has no POSITION attribute".
std::string gltfClaimProblem(const std::filesystem::path& file);

}  // namespace probeproxy
