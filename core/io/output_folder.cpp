#include "core/io/output_folder.h"

#include "core/errors/input_error.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

namespace probeproxy {

void checkOutputFolder(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path existing = fs::absolute(folder.empty() ? fs::path(".") : folder, error);
  if (error) throw InputError(folder, "output folder: " + error.message());
  existing = existing.lexically_normal();
  while (!fs::exists(existing, error) && existing.has_relative_path()) {
    existing = existing.parent_path();
  }
  if (!fs::is_directory(existing, error)) {
    throw InputError(folder,
                     "output folder cannot be made: " + existing.string() + " is not a folder");
  }
  // Permission bits do not tell (root may write anywhere, except in /proc or on a read-only
  // mount): make and remove a folder where the output would go.
  const fs::path probe =
      existing / (".probeproxy-write-check-" + std::to_string(static_cast<long>(::getpid())));
  if (::mkdir(probe.c_str(), 0700) != 0) {
    throw InputError(folder, "output folder cannot be made or written in " + existing.string() +
                                 ": " + std::generic_category().message(errno));
  }
  ::rmdir(probe.c_str());
}

}  // namespace probeproxy
