#include "geometry/level/bsp/pk3_archive.h"

#include "core/errors/input_error.h"
#include "core/io/regular_file.h"
#include "core/scene/scene_limits.h"

#include <zip.h>

#include <memory>
#include <string>
#include <system_error>

namespace probeproxy {

namespace {

struct ArchiveCloser {
  void operator()(zip_t* archive) const { zip_discard(archive); }  // read-only: nothing to save
};
struct EntryCloser {
  void operator()(zip_file_t* entry) const { zip_fclose(entry); }
};

std::string zipErrorText(int code) {
  zip_error_t error;
  zip_error_init_with_code(&error, code);
  std::string text = zip_error_strerror(&error);
  zip_error_fini(&error);
  return text;
}

}  // namespace

std::vector<std::byte> readFileFromPk3(const std::filesystem::path& archive,
                                       const std::filesystem::path& entry) {
  requireRegularFile(archive, "archive");
  int openError = 0;
  const std::unique_ptr<zip_t, ArchiveCloser> zip(
      zip_open(archive.c_str(), ZIP_RDONLY, &openError));
  if (!zip) throw InputError(archive, "not a readable .pk3 (zip): " + zipErrorText(openError));

  const std::string name = entry.generic_string();
  const zip_int64_t index = zip_name_locate(zip.get(), name.c_str(), ZIP_FL_NOCASE);
  if (index < 0) throw InputError(archive, "no \"" + name + "\" inside the archive");
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat_index(zip.get(), zip_uint64_t(index), 0, &stat) != 0 ||
      !(stat.valid & ZIP_STAT_SIZE)) {
    throw InputError(archive, "\"" + name + "\": " + zip_strerror(zip.get()));
  }
  // The size the archive claims, checked before the buffer is taken: a few kilobytes of zip can
  // claim (and a deflate stream can inflate to) gigabytes. The reads below stop at the claimed
  // size, so a stream that inflates past its claim does not get further.
  if (stat.size > inputLimits().maxFileBytes()) {
    throw InputError(archive, fileLimitProblem("\"" + name + "\" inflated", stat.size));
  }
  const std::unique_ptr<zip_file_t, EntryCloser> file(
      zip_fopen_index(zip.get(), zip_uint64_t(index), 0));
  if (!file) throw InputError(archive, "\"" + name + "\": " + zip_strerror(zip.get()));

  std::vector<std::byte> bytes(stat.size);
  zip_uint64_t done = 0;
  while (done < stat.size) {
    const zip_int64_t got = zip_fread(file.get(), bytes.data() + done, stat.size - done);
    if (got < 0) {
      throw InputError(archive, "\"" + name + "\": " + zip_file_strerror(file.get()));
    }
    if (got == 0) break;
    done += zip_uint64_t(got);
  }
  if (done != stat.size) {
    throw InputError(archive, "\"" + name + "\": archive entry ends after " + std::to_string(done) +
                                  " of " + std::to_string(stat.size) + " bytes");
  }
  // libzip compares the CRC only when a read reaches the end of the entry, which reading
  // exactly the claimed size never does.
  char past = 0;
  const zip_int64_t more = zip_fread(file.get(), &past, 1);
  if (more < 0) {
    throw InputError(archive, "\"" + name + "\": " + zip_file_strerror(file.get()) +
                                  " (its bytes are not those the archive recorded)");
  }
  if (more > 0) {
    throw InputError(archive, "\"" + name + "\": archive entry holds more than the " +
                                  std::to_string(stat.size) + " bytes it claims");
  }
  return bytes;
}

}  // namespace probeproxy
