#include "core/io/atomic_write.h"

#include "core/errors/input_error.h"
#include "core/io/regular_file.h"

#include <unistd.h>
#include <fstream>
#include <system_error>

namespace probeproxy {

namespace {

std::filesystem::path temporaryBeside(const std::filesystem::path& target) {
  // Same folder, so the rename cannot cross file systems; the pid keeps two runs apart.
  // The extension is kept so that writers choosing a format by extension still see it.
  std::filesystem::path tmp = target;
  std::string name = ".";
  name += target.stem().string();
  name += ".tmp" + std::to_string(::getpid());
  name += target.extension().string();
  tmp.replace_filename(name);
  return tmp;
}

}  // namespace

void requireReplaceableFiles(std::span<const std::filesystem::path> targets) {
  for (const std::filesystem::path& target : targets) {
    std::error_code ec;
    if (std::filesystem::exists(target, ec)) requireRegularFile(target, "output");
  }
}

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& writeTo) {
  requireReplaceableFiles(std::span(&target, 1));
  if (target.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(target.parent_path(), ec);
    if (ec) throw InputError(target, "cannot create folder: " + ec.message());
  }
  const std::filesystem::path tmp = temporaryBeside(target);
  try {
    writeTo(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(target, "cannot write: " + ec.message());
  }
}

void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes) {
  writeFileAtomically(target, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw InputError(target, "cannot write");
  });
}

}  // namespace probeproxy
