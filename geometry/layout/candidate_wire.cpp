#include "geometry/layout/candidate_wire.h"

#include "core/errors/input_error.h"
#include "geometry/layout/wire_bytes.h"

#include <cstdint>
#include <stdexcept>

namespace probeproxy {

namespace {

constexpr std::string_view kMagic = "PPCW";
constexpr std::uint32_t kVersion = 1;

void putSet(std::string& out, const IndexSet& set) {
  const std::size_t bytes = set.getSizeInBytes();
  wire::put<std::uint64_t>(out, bytes);
  const std::size_t at = out.size();
  out.resize(at + bytes);
  set.write(out.data() + at);
}

IndexSet getSet(wire::Reader& in) {
  const auto n = in.get<std::uint64_t>();
  const std::string_view part = in.take(n);
  IndexSet set;
  try {
    set = IndexSet::readSafe(part.data(), part.size());
  } catch (const std::runtime_error&) {  // CRoaring's word for any bitmap it cannot read
    throw InputError(in.what, "a bitmap of " + std::to_string(n) + " bytes that is not one");
  }
  if (set.getSizeInBytes() != n)
    throw InputError(in.what, "a bitmap of " + std::to_string(n) + " bytes reads as another");
  return set;
}

}  // namespace

std::string packCandidates(std::span<const CaptureCandidates> captures) {
  std::string out(kMagic);
  wire::put(out, kVersion);
  wire::put<std::uint64_t>(out, captures.size());
  for (const CaptureCandidates& c : captures) {
    wire::put<std::uint64_t>(out, c.capture);
    wire::put<std::uint64_t>(out, c.sight.raysCast);
    putSet(out, c.sight.seen);
    wire::put<std::uint32_t>(out, static_cast<std::uint32_t>(c.services.size()));
    for (const CandidateService& s : c.services) {
      wire::put(out, s.fitMeters);
      wire::put(out, s.buildMs);
      putSet(out, s.served);
    }
  }
  return out;
}

std::vector<CaptureCandidates> unpackCandidates(std::string_view bytes) {
  wire::Reader in{"candidate wire", bytes};
  in.expectHeader(kMagic, "packed candidates", kVersion);
  const auto count = in.get<std::uint64_t>();
  std::vector<CaptureCandidates> captures;
  for (std::uint64_t k = 0; k < count; ++k) {
    CaptureCandidates c;
    c.capture = in.get<std::uint64_t>();
    c.sight.raysCast = in.get<std::uint64_t>();
    c.sight.seen = getSet(in);
    const auto services = in.get<std::uint32_t>();
    for (std::uint32_t f = 0; f < services; ++f) {
      CandidateService s;
      s.capture = c.capture;
      s.fitMeters = in.get<double>();
      s.buildMs = in.get<double>();
      s.served = getSet(in);
      c.services.push_back(std::move(s));
    }
    captures.push_back(std::move(c));
  }
  in.expectEnd("the last capture point");
  return captures;
}

}  // namespace probeproxy
