#include "core/io/regular_file.h"

#include "core/errors/input_error.h"

namespace probeproxy {

namespace {

const char* kindOf(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::directory:
      return "a folder";
    case std::filesystem::file_type::fifo:
      return "a FIFO";
    case std::filesystem::file_type::character:
    case std::filesystem::file_type::block:
      return "a device";
    case std::filesystem::file_type::socket:
      return "a socket";
    default:
      return "not a file";
  }
}

}  // namespace

void requireRegularFile(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (status.type() == std::filesystem::file_type::not_found || ec)
    throw InputError(file, what + " not found");
  if (status.type() == std::filesystem::file_type::regular) return;
  throw InputError(file, what + " is " + kindOf(status.type()) + ", not a regular file");
}

}  // namespace probeproxy
