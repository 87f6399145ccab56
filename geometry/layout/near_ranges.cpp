#include "geometry/layout/near_ranges.h"

#include "geometry/layout/floor_rectangles.h"
#include "geometry/layout/layout_influence.h"

#include <algorithm>
#include <optional>

namespace probeproxy {

namespace {

// Ranges this many gaps apart keep the blend's steepest change across them at
// 1 / (g (1 - g / (2 b))) = 1.86 per metre with the layout's bands (b = 1.5 gaps), under
// validate's 2: parting them further would only push a range's floor into the far ends of
// bands for nothing (bloodprison's probe_005 parted the whole gap: p95 +0.36 deg).
constexpr double kSmoothGapOverGap = 0.7;

// How far the `side` face of the range along `axis` can move in, its capture point staying a
// margin inside.
double roomToGive(const InnerRange& range, glm::dvec3 captureMeters, int axis, int side) {
  const double room = side > 0 ? range.hi[axis] - (captureMeters[axis] + kCaptureMarginMeters)
                               : (captureMeters[axis] - kCaptureMarginMeters) - range.lo[axis];
  return std::max(0.0, room);
}

// Parts `a` (one of the layout's own) from `other` (its own too, or kept when null) that much.
void partToSmoothGap(double gapMeters, LayoutProbe& a, const InnerRange& otherRange,
                     LayoutProbe* other) {
  const std::optional<InnerRange> range = innerRangeOf(a.influence);
  if (!range || !overlapInHeight(*range, otherRange)) return;
  const PlanGap apart = planGap(*range, otherRange);
  const double smoothGap = kSmoothGapOverGap * gapMeters;
  if (apart.meters < 0.0 || apart.meters >= smoothGap) return;
  const int axis = apart.axis, side = apart.side;  // a's side facing the other
  const double missing = smoothGap - apart.meters;
  const double roomA = roomToGive(*range, a.captureMeters, axis, side);
  const double roomOther = other ? roomToGive(otherRange, other->captureMeters, axis, -side) : 0.0;
  // The one with more room gives first (the other on a tie): a thin range stays as it is.
  const bool aFirst = roomA > roomOther;
  const double first = std::min(aFirst ? roomA : roomOther, missing);
  const double second = std::min(aFirst ? roomOther : roomA, missing - first);
  const double cutA = aFirst ? first : second, cutOther = aFirst ? second : first;
  if (cutA > 0.0)
    a.influence = withFaceMovedIn(std::get<BoxInfluence>(a.influence), axis, side, cutA);
  if (other && cutOther > 0.0)
    other->influence =
        withFaceMovedIn(std::get<BoxInfluence>(other->influence), axis, -side, cutOther);
}

}  // namespace

void partNearRanges(double gapMeters, std::span<const InfluenceVolume> kept,
                    std::vector<LayoutProbe>& probes) {
  for (LayoutProbe& probe : probes)
    for (const InfluenceVolume& k : kept)
      if (const std::optional<InnerRange> range = innerRangeOf(k))
        partToSmoothGap(gapMeters, probe, *range, nullptr);
  for (std::size_t i = 0; i < probes.size(); ++i)
    for (std::size_t j = i + 1; j < probes.size(); ++j)
      if (const std::optional<InnerRange> range = innerRangeOf(probes[j].influence))
        partToSmoothGap(gapMeters, probes[i], *range, &probes[j]);
}

}  // namespace probeproxy
