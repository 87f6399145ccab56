#include "geometry/layout/candidate_wire.h"

#include "core/errors/input_error.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace probeproxy {

namespace {

constexpr std::string_view kMagic = "PPCW";
constexpr const char* kWhat = "candidate wire";
constexpr std::uint32_t kVersion = 1;

static_assert(std::endian::native == std::endian::little, "the wire is written as in memory");

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void putSet(std::string& out, const IndexSet& set) {
  const std::size_t bytes = set.getSizeInBytes();
  put<std::uint64_t>(out, bytes);
  const std::size_t at = out.size();
  out.resize(at + bytes);
  set.write(out.data() + at);
}

struct Reader {
  std::string_view bytes;
  std::size_t at = 0;

  std::string_view take(std::size_t n) {
    if (n > bytes.size() - at)
      throw InputError(kWhat, std::to_string(bytes.size()) + " bytes end at " + std::to_string(at) +
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
  IndexSet getSet() {
    const auto n = get<std::uint64_t>();
    const std::string_view part = take(n);
    IndexSet set;
    try {
      set = IndexSet::readSafe(part.data(), part.size());
    } catch (const std::runtime_error&) {  // CRoaring's word for any bitmap it cannot read
      throw InputError(kWhat, "a bitmap of " + std::to_string(n) + " bytes that is not one");
    }
    if (set.getSizeInBytes() != n)
      throw InputError(kWhat, "a bitmap of " + std::to_string(n) + " bytes reads as another");
    return set;
  }
};

}  // namespace

std::string packCandidates(std::span<const CaptureCandidates> captures) {
  std::string out(kMagic);
  put(out, kVersion);
  put<std::uint64_t>(out, captures.size());
  for (const CaptureCandidates& c : captures) {
    put<std::uint64_t>(out, c.capture);
    put<std::uint64_t>(out, c.sight.raysCast);
    putSet(out, c.sight.seen);
    put<std::uint32_t>(out, static_cast<std::uint32_t>(c.services.size()));
    for (const CandidateService& s : c.services) {
      put(out, s.fitMeters);
      put(out, s.buildMs);
      putSet(out, s.served);
    }
  }
  return out;
}

std::vector<CaptureCandidates> unpackCandidates(std::string_view bytes) {
  Reader in{bytes};
  if (in.take(kMagic.size()) != kMagic)
    throw InputError(kWhat, "not packed candidates (no PPCW header)");
  if (const auto version = in.get<std::uint32_t>(); version != kVersion)
    throw InputError(kWhat, "version " + std::to_string(version) + ", this program reads " +
                                std::to_string(kVersion));
  const auto count = in.get<std::uint64_t>();
  std::vector<CaptureCandidates> captures;
  for (std::uint64_t k = 0; k < count; ++k) {
    CaptureCandidates c;
    c.capture = in.get<std::uint64_t>();
    c.sight.raysCast = in.get<std::uint64_t>();
    c.sight.seen = in.getSet();
    const auto services = in.get<std::uint32_t>();
    for (std::uint32_t f = 0; f < services; ++f) {
      CandidateService s;
      s.capture = c.capture;
      s.fitMeters = in.get<double>();
      s.buildMs = in.get<double>();
      s.served = in.getSet();
      c.services.push_back(std::move(s));
    }
    captures.push_back(std::move(c));
  }
  if (in.at != bytes.size())
    throw InputError(kWhat,
                     std::to_string(bytes.size() - in.at) + " bytes after the last capture point");
  return captures;
}

}  // namespace probeproxy
