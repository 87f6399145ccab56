#pragma once
// Output folders are checked before a job starts its work, so no one waits a whole bench to
// learn that `--out` cannot be written, and nothing is left half-written.

#include <filesystem>

namespace probeproxy {

// Throws InputError naming `folder` unless it is a writable folder or can be made as one: its
// nearest existing ancestor is a writable folder and nothing on the way is a file. Creates
// nothing. An empty path is the working folder.
void checkOutputFolder(const std::filesystem::path& folder);

}  // namespace probeproxy
