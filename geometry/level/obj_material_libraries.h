#pragma once
// An OBJ's `mtllib` lines name files Assimp opens beside it. A FIFO there would block the load
// for ever, a folder fail deep in Assimp; each named library that exists must be a regular
// file. A missing one is Assimp's to warn about: the level's geometry does not need it.

#include <filesystem>

namespace probeproxy {

// Throws InputError naming the library ("... is a FIFO, not a regular file").
void requireReadableMaterialLibraries(const std::filesystem::path& obj);

}  // namespace probeproxy
