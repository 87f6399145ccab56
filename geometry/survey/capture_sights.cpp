#include "geometry/survey/capture_sights.h"

#include "geometry/evaluation/reflection_samples.h"

namespace probeproxy {

CaptureSights::CaptureSights(const SurveyFloor& floor)
    : floor_(floor), known_(floor.samples.size()) {}

std::vector<std::uint32_t> CaptureSights::idsOf(std::span<const EngineProbe> probes) {
  std::vector<std::uint32_t> ids;
  ids.reserve(probes.size());
  for (const EngineProbe& probe : probes) {
    const glm::dvec3& c = probe.captureMeters;
    const auto [at, added] =
        ids_.try_emplace({c.x, c.y, c.z}, static_cast<std::uint32_t>(captures_.size()));
    if (added) captures_.push_back(c);
    ids.push_back(at->second);
  }
  return ids;
}

bool CaptureSights::hidden(const LevelRayCaster& level, std::size_t sample, std::uint32_t id) {
  std::vector<std::uint8_t>& known = known_[sample];
  if (known.size() <= id / 4) known.resize(captures_.size() / 4 + 1, 0);
  const unsigned shift = 2 * (id % 4);
  const unsigned state = (known[id / 4] >> shift) & 3u;
  if (state != 0) return state == 2;
  const bool isHidden = trueHitHiddenFrom(level, captures_[id], floor_.samples[sample].sample);
  known[id / 4] |= static_cast<std::uint8_t>((isHidden ? 2u : 1u) << shift);
  return isHidden;
}

}  // namespace probeproxy
