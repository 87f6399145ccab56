#pragma once
// What a capture point's candidates send back from wherever they were judged (a tile of the
// floor, another process, another machine) to the selection: the samples its capture point
// sees and, for each fit region, the region's radius and the samples its proxy serves within
// the tolerance. The proxies stay behind: the chosen probes are built again with the final
// options. Bytes: a header ("PPCW", version, count), then per capture point its index, the
// rays its sight cast, its bitmap, its fit regions and theirs, little-endian, the bitmaps in
// CRoaring's portable format (which the Java and Go Roaring libraries read too). Unpacking
// gives back exactly what was packed, so the layout is the same bytes however it was split.

#include "geometry/layout/candidate_service.h"
#include "geometry/layout/capture_sight.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace probeproxy {

struct CaptureCandidates {
  std::size_t capture = 0;  // index of the capture point in the layout's candidates
  CaptureSight sight;
  std::vector<CandidateService> services;  // fit regions, smallest first; no proxy
};

std::string packCandidates(std::span<const CaptureCandidates> captures);

// Throws InputError ("candidate wire: ...") naming what is wrong with bytes packCandidates did
// not write.
std::vector<CaptureCandidates> unpackCandidates(std::string_view bytes);

}  // namespace probeproxy
