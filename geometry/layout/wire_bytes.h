#pragma once
// The byte level of what a layout sends between processes (candidate_wire.h,
// proxy_build_wire.h): numbers little-endian as in memory, doubles as their bits (so what is
// read back is exactly what was packed), strings and arrays after their length. A reader
// refuses what runs short, too long or out of range with an InputError naming its wire.

#include "core/errors/input_error.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace probeproxy::wire {

static_assert(std::endian::native == std::endian::little, "the wires are written as in memory");

template <class T>
void put(std::string& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

inline void putString(std::string& out, std::string_view text) {
  put<std::uint64_t>(out, text.size());
  out.append(text);
}

struct Reader {
  const char* what;  // the wire's name, first in every refusal
  std::string_view bytes;
  std::size_t at = 0;

  std::string_view take(std::size_t n) {
    if (n > bytes.size() - at)
      throw InputError(what, std::to_string(bytes.size()) + " bytes end at " + std::to_string(at) +
                                 ", " + std::to_string(n) + " more expected");
    const std::string_view part = bytes.substr(at, n);
    at += n;
    return part;
  }
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof value).data(), sizeof value);
    return value;
  }
  std::string getString() { return std::string(take(get<std::uint64_t>())); }
  // A count of items of at least `itemBytes` each: one the bytes left cannot hold is refused
  // before anything is allocated for it.
  std::uint64_t getCount(std::size_t itemBytes) {
    const auto n = get<std::uint64_t>();
    if (itemBytes > 0 && n > (bytes.size() - at) / itemBytes)
      throw InputError(what, std::to_string(n) + " items of " + std::to_string(itemBytes) +
                                 "+ bytes at " + std::to_string(at) + " in " +
                                 std::to_string(bytes.size()) + " bytes");
    return n;
  }
  // The header: `magic`, then this version.
  void expectHeader(std::string_view magic, std::string_view whatFor, std::uint32_t version) {
    if (take(std::min(magic.size(), bytes.size())) != magic)
      throw InputError(what,
                       "not " + std::string(whatFor) + " (no " + std::string(magic) + " header)");
    if (const auto got = get<std::uint32_t>(); got != version)
      throw InputError(what, "version " + std::to_string(got) + ", this program reads " +
                                 std::to_string(version));
  }
  void expectEnd(std::string_view afterWhat) const {
    if (at != bytes.size())
      throw InputError(
          what, std::to_string(bytes.size() - at) + " bytes after " + std::string(afterWhat));
  }
};

}  // namespace probeproxy::wire
