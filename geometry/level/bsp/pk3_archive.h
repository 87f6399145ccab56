#pragma once
// Reading one file out of a .pk3 (a zip archive, as Quake 3 packs its data) with libzip.
// Names are matched ignoring case, as the game's file system does.

#include <cstddef>
#include <filesystem>
#include <vector>

namespace probeproxy {

// Throws InputError(archive, ...) when the archive cannot be opened or read, or holds no
// entry named `entry`.
std::vector<std::byte> readFileFromPk3(const std::filesystem::path& archive,
                                       const std::filesystem::path& entry);

}  // namespace probeproxy
