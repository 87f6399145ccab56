#pragma once
// What a glTF or GLB file must hold before Assimp reads it. Debian's Assimp 5.2.5 trusts it:
// a line loop (mode 2) whose indices or positions are not what they claim makes its glTF2
// importer read through a null pointer, with or without a POSITION attribute (found by
// fuzz_level_glb). probeproxy reads triangles, and neither a line loop nor a primitive without
// positions has any, so such a file is refused first, naming the primitive. So is one whose
// buffers declare more bytes than --max-file-mb (a .gltf's buffers may be other files).

#include <filesystem>
#include <string>

namespace probeproxy {

// Empty when every mesh primitive of the file's JSON (the .gltf, or a .glb's JSON chunk) has a
// POSITION attribute and is no line loop, or when the JSON does not parse (Assimp then says
// what is wrong); otherwise the problem, e.g. "glTF mesh 0 primitive 0 has no POSITION
// attribute".
std::string gltfClaimProblem(const std::filesystem::path& file);

}  // namespace probeproxy
