#pragma once
// The lump directory of a Quake 3 BSP file (`IBSP` version 46: Quake III, Nexuiz, Xonotic,
// Tremulous...; id Software's code/qcommon/qfiles.h). A view over bytes the caller owns:
// every offset and length is checked against the file's size once, here, so the readers of
// each lump only ever index inside their own span. Records are little-endian, as the format
// fixes; they are copied out with memcpy, never read through a cast pointer (alignment).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace probeproxy {

enum class BspLump : int {
  Entities = 0,
  Shaders = 1,
  Planes = 2,
  Nodes = 3,
  Leafs = 4,
  LeafSurfaces = 5,
  LeafBrushes = 6,
  Models = 7,
  Brushes = 8,
  BrushSides = 9,
  DrawVerts = 10,
  DrawIndexes = 11,
  Fogs = 12,
  Surfaces = 13,
  Lightmaps = 14,
  LightGrid = 15,
  Visibility = 16,
};
inline constexpr int kBspLumpCount = 17;
inline constexpr int kBspVersion = 46;
inline constexpr std::size_t kBspHeaderBytes = 8 + 8 * kBspLumpCount;  // ident, version, lumps

// "lump 13 (surfaces)": how errors name a lump.
std::string bspLumpName(BspLump lump);

// A checked view of one BSP file. Does not own the bytes.
class BspLumps {
 public:
  // Checks the header (ident, version) and that every lump lies inside `bytes`; throws
  // InputError(file, "...") naming the first lump that does not.
  BspLumps(std::span<const std::byte> bytes, std::filesystem::path file);

  std::span<const std::byte> bytes(BspLump lump) const;

  // The lump as `recordBytes`-sized records: throws when its length is not a whole number of
  // them.
  std::size_t recordCount(BspLump lump, std::size_t recordBytes) const;

  const std::filesystem::path& file() const { return file_; }

  // Throws InputError(file, "<lump name>: <problem>").
  [[noreturn]] void fail(BspLump lump, const std::string& problem) const;

 private:
  std::span<const std::byte> file_bytes_;
  std::filesystem::path file_;
  std::size_t offsets_[kBspLumpCount] = {};
  std::size_t lengths_[kBspLumpCount] = {};
};

// Little-endian scalars at `offset` in `bytes`; the caller has checked the range.
std::int32_t bspInt32(std::span<const std::byte> bytes, std::size_t offset);
float bspFloat(std::span<const std::byte> bytes, std::size_t offset);

}  // namespace probeproxy
