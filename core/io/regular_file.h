#pragma once
// Every input is read from a regular file: opening a FIFO blocks until someone writes to it,
// /dev/zero never ends, and a folder opens but does not read. Checked before a reader opens
// the path, so each of them answers with one line instead of hanging.

#include <filesystem>
#include <string>

namespace probeproxy {

// Throws InputError(file, "<what> not found") when nothing is there, or "<what> is a FIFO, not
// a regular file" (a folder, a device, a socket) when it is not a file.
void requireRegularFile(const std::filesystem::path& file, const std::string& what);

}  // namespace probeproxy
