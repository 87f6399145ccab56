#include "geometry/layout/thin_ranges.h"

#include "geometry/layout/bands_in_sight.h"
#include "geometry/layout/layout_influence.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <optional>

namespace probeproxy {

namespace {

// Ranges of one height window: a join across storeys would span the slab.
constexpr double kSameWindowMeters = 0.5;

}  // namespace

void joinThinRanges(const LevelRayCaster& level, const WalkableFloor& walked, double gapMeters,
                    std::span<const InfluenceVolume> kept, std::vector<LayoutProbe>& probes) {
  constexpr double kSlack = 1e-6;
  std::vector<std::optional<InnerRange>> ranges;
  for (const LayoutProbe& p : probes) ranges.push_back(innerRangeOf(p.influence));
  std::vector<InnerRange> fixed;
  for (const InfluenceVolume& v : kept)
    if (const std::optional<InnerRange> r = innerRangeOf(v)) fixed.push_back(*r);
  std::vector<char> gone(probes.size(), 0);
  for (std::size_t t = 0; t < probes.size(); ++t) {
    if (gone[t] || !ranges[t]) continue;
    const InnerRange thin = *ranges[t];
    const glm::dvec3 size = thin.hi - thin.lo;
    if (std::min(size.x, size.y) >= gapMeters - kSlack) continue;
    std::optional<std::size_t> best;
    InnerRange bestUnion;
    double bestApart = 0.0;
    for (std::size_t n = 0; n < probes.size(); ++n) {
      if (n == t || gone[n] || !ranges[n]) continue;
      const InnerRange& wide = *ranges[n];
      if (std::abs(wide.lo.z - thin.lo.z) > kSameWindowMeters ||
          std::abs(wide.hi.z - thin.hi.z) > kSameWindowMeters)
        continue;
      const glm::dvec3 wideSize = wide.hi - wide.lo;
      if (wideSize.x * wideSize.y <= size.x * size.y) continue;
      const double apart = planApart(thin, wide);
      if (apart < -kSlack || apart > gapMeters + kSlack) continue;
      const InnerRange joined{glm::min(thin.lo, wide.lo), glm::max(thin.hi, wide.hi)};
      // The union keeps the gap that the two kept from every other range.
      const auto keepsClear = [&](const InnerRange& other) {
        if (!overlapInHeight(joined, other)) return true;
        const double before = std::min({planApart(thin, other), planApart(wide, other), gapMeters});
        return planApart(joined, other) >= before - kSlack;
      };
      bool clear = std::all_of(fixed.begin(), fixed.end(), keepsClear);
      for (std::size_t o = 0; clear && o < probes.size(); ++o)
        if (o != t && o != n && !gone[o] && ranges[o]) clear = keepsClear(*ranges[o]);
      if (!clear || (best && apart >= bestApart)) continue;
      best = n, bestUnion = joined, bestApart = apart;
    }
    if (!best) continue;
    LayoutProbe& wide = probes[*best];
    // Only where the joined band stays in sight of the wider probe whole: a thin range is often
    // a side pulled in from a wall, and its band, reaching on from the wider one's capture
    // point, would look through it (bloodprison: 5.5% behind a wall after the pull).
    InnerRange joined = bestUnion;
    pullBandsIntoSight(level, walked, wide.captureMeters, gapMeters, joined.lo, joined.hi);
    if (joined.lo != bestUnion.lo || joined.hi != bestUnion.hi) continue;
    wide.influence = influenceOfBounds(joined.lo, joined.hi, gapMeters);
    ranges[*best] = joined;
    gone[t] = 1;
  }
  std::vector<LayoutProbe> left;
  for (std::size_t i = 0; i < probes.size(); ++i)
    if (!gone[i]) left.push_back(std::move(probes[i]));
  probes = std::move(left);
}

}  // namespace probeproxy
