#include "core/proxy/proxy_candidate.h"

namespace probeproxy {

std::string candidateName(const ProxyCandidate& c) {
  switch (c.origin) {
    case CandidateOrigin::Authored:
      return "authored";
    case CandidateOrigin::Infinite:
      return "infinite";
    case CandidateOrigin::CheapK:
      return "cheap_k";
    case CandidateOrigin::Sphere:
      return "sphere";
    case CandidateOrigin::MinSphere:
      return "min_sphere";
    case CandidateOrigin::Aabb:
      return "aabb";
    case CandidateOrigin::Obb:
      return "obb";
    case CandidateOrigin::RoomBox:
      return "room_box";
    case CandidateOrigin::Hull:
      return "hull";
    case CandidateOrigin::Simplified:
      return "convex_" + std::to_string(planeCount(c.shape));
  }
  return "unknown";
}

}  // namespace probeproxy
