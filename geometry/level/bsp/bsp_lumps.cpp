#include "geometry/level/bsp/bsp_lumps.h"

#include "core/errors/input_error.h"

#include <bit>
#include <cstring>

namespace probeproxy {

namespace {

constexpr const char* kLumpNames[kBspLumpCount] = {
    "entities",    "shaders",  "planes",    "nodes",      "leafs",     "leafsurfaces",
    "leafbrushes", "models",   "brushes",   "brushsides", "drawverts", "drawindexes",
    "fogs",        "surfaces", "lightmaps", "lightgrid",  "visibility"};

std::uint32_t littleEndianU32(std::span<const std::byte> bytes, std::size_t offset) {
  std::uint8_t b[4];
  std::memcpy(b, bytes.data() + offset, 4);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

}  // namespace

std::string bspLumpName(BspLump lump) {
  const int index = static_cast<int>(lump);
  return "lump " + std::to_string(index) + " (" + kLumpNames[index] + ")";
}

std::int32_t bspInt32(std::span<const std::byte> bytes, std::size_t offset) {
  return std::bit_cast<std::int32_t>(littleEndianU32(bytes, offset));
}

float bspFloat(std::span<const std::byte> bytes, std::size_t offset) {
  return std::bit_cast<float>(littleEndianU32(bytes, offset));
}

BspLumps::BspLumps(std::span<const std::byte> bytes, std::filesystem::path file)
    : file_bytes_(bytes), file_(std::move(file)) {
  if (bytes.size() < kBspHeaderBytes) {
    throw InputError(file_, "not a Quake 3 BSP: " + std::to_string(bytes.size()) +
                                " bytes, shorter than the " + std::to_string(kBspHeaderBytes) +
                                "-byte header");
  }
  if (std::memcmp(bytes.data(), "IBSP", 4) != 0) {
    throw InputError(file_, "not a Quake 3 BSP: the file does not start with \"IBSP\"");
  }
  const std::int32_t version = bspInt32(bytes, 4);
  if (version != kBspVersion) {
    throw InputError(
        file_, "unsupported BSP version " + std::to_string(version) + " (expected 46, Quake III)");
  }
  for (int i = 0; i < kBspLumpCount; ++i) {
    const auto lump = static_cast<BspLump>(i);
    const std::int64_t offset = bspInt32(bytes, 8 + 8 * i);
    const std::int64_t length = bspInt32(bytes, 12 + 8 * i);
    if (offset < 0 || length < 0) {
      fail(lump,
           "negative offset " + std::to_string(offset) + " or length " + std::to_string(length));
    }
    // 64-bit sums: offset + length cannot overflow what the header can say.
    if (offset + length > static_cast<std::int64_t>(bytes.size())) {
      fail(lump, "runs past the end of the file (offset " + std::to_string(offset) + " + length " +
                     std::to_string(length) + " > " + std::to_string(bytes.size()) + " bytes)");
    }
    offsets_[i] = static_cast<std::size_t>(offset);
    lengths_[i] = static_cast<std::size_t>(length);
  }
}

std::span<const std::byte> BspLumps::bytes(BspLump lump) const {
  const int i = static_cast<int>(lump);
  return file_bytes_.subspan(offsets_[i], lengths_[i]);
}

std::size_t BspLumps::recordCount(BspLump lump, std::size_t recordBytes) const {
  const std::size_t length = lengths_[static_cast<int>(lump)];
  if (length % recordBytes != 0) {
    fail(lump, "length " + std::to_string(length) + " is not a whole number of " +
                   std::to_string(recordBytes) + "-byte records");
  }
  return length / recordBytes;
}

void BspLumps::fail(BspLump lump, const std::string& problem) const {
  throw InputError(file_, bspLumpName(lump) + ": " + problem);
}

}  // namespace probeproxy
