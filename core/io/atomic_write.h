#pragma once
// Every file probeproxy writes appears whole or not at all: the bytes go to a temporary file
// beside the target, which is renamed over it only once complete. A crash or a bad input
// half-way never leaves a truncated proxies.json for a game build to pick up.

#include <filesystem>
#include <functional>
#include <span>
#include <string_view>

namespace probeproxy {

void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

// Before a job writes several files: each target that exists must be a regular file. A folder
// there fails only its own rename, after the files before it were written; checked first, the
// job writes all of them or none.
void requireReplaceableFiles(std::span<const std::filesystem::path> targets);

// For writers that need a path (OpenImageIO, Assimp): `writeTo` writes the temporary file
// it is given; the rename happens only if it returns without throwing.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& writeTo);

}  // namespace probeproxy
