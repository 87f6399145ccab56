#pragma once
// Which candidates become probes, and the floor each one's inner range holds (docs/layout.md).
// Lagarde's blend gives a box's probe 100% inside its inner range, so the selection picks
// candidates together with their ranges: rectangles of floor (floor_rectangles.h) grown from
// each capture point over the floor its proxy serves within the tolerance (as well as any
// candidate does there, then looser, `SelectionOptions::passes`), never over floor out of its
// sight (floor_in_sight.h: such floor would leak), no two within the blend band of each other.
// Greedy by area: each step takes the candidate whose rectangle holds the most floor it serves
// (samples served, ties to the lower index), until none gains `minGainSquareMeters`. Floor no
// candidate serves goes to the candidates that see it, in the same rectangles. Then the floor
// left outside every range and band goes, the same way, to the candidates that see it (those
// that serve it first); crumbs smaller than the gain a probe must bring stretch the nearest
// range until its band holds them, and what no range can stretch to without breaking a gap is
// a fill. With `maxProbes`, the cover stops at that many. A one-storey floor that one candidate
// serves nearly as well as the whole cover gets that one probe. Deterministic whatever the
// thread count.

#include "geometry/floor/walkable_floor.h"
#include "geometry/layout/candidate_service.h"
#include "geometry/layout/capture_sight.h"
#include "geometry/layout/floor_in_sight.h"
#include "geometry/layout/floor_rectangles.h"

#include <cstddef>
#include <span>
#include <vector>

namespace probeproxy {

struct SelectionOptions {
  std::size_t maxProbes = 0;  // 0: no limit
  int gapCells = 2;           // floor cells between two inner ranges (the blend band)
  // A probe must bring at least the larger of these: a probe for a crumb of floor costs a
  // cubemap and a blend band, and its band disturbs the neighbours that already shade it.
  double minGainSquareMeters = 1.0;
  double minGainShare = 0.001;  // of the walkable floor's area
  // The cover's passes, each run to the end. In each, a rectangle grows by a strip its probe
  // serves, on average over the strip's floor, at least `acceptedShare` as well as the best
  // candidate there does (the share of a cell's samples served within the tolerance): ranges as
  // good as any candidate's first, only where they bring `minGainSquareMeters` (an exact range a
  // few cells wide costs a blend band around it, floor that blends two probes), then looser
  // ones. Whole cells served once decided (warfare: ranges stopped at a cell or two, where a
  // neighbouring cell's sample missed, and half the floor went to ranges that only saw it).
  struct CoverPass {
    double acceptedShare = 0.8;
    double minGainSquareMeters = 0.0;  // under the cover's least gain: that gain
  };
  std::vector<CoverPass> passes = {{0.99, 8.0}, {0.8, 0.0}, {0.6, 0.0}};
  // The floor left after the passes goes to the candidates that see it, in strips of which this
  // share is in sight; a probe whose range a neighbour can take over goes when the neighbour
  // serves this share of the floor it gains.
  double acceptedShare = 0.9;
  // One probe is the layout when one candidate alone serves (in samples) at least acceptedShare
  // of the floor and at most this share less than the whole cover does (on a one-storey floor):
  // the hangar, a box room with two blocks, had 13 probes for a few percent of its floor.
  double oneProbeSlack = 0.02;
};

struct ProbeSelection {
  std::vector<std::size_t> chosen;  // candidate indices, in the order they were taken
  std::vector<FloorRect> ranges;    // chosen[i]'s inner range
  // Floor no range's band could reach without coming within the band of another: each gets a
  // probe of its own, captured over it (no candidate was fitted there). Left to a band's far
  // edge, every weight over it would tend to 0 and the blend would pop.
  std::vector<FloorRect> fills;
};

// Probes the cover keeps as they are (an artist's, `layout --keep-authored`): per floor cell,
// whether one of their volumes covers it, and whether they already serve it (covered, every
// sample within the tolerance). Served cells are no new probe's; covered ones need no stretch.
struct KeptFloor {
  std::vector<char> covered, served;
};

// `sights[services[c].capture]` is what candidate c sees; `captureCells[services[c].capture]`
// the floor cell under its capture point; `inSight` which floor it holds in sight (a range
// holds no other). `kept`: empty, or per floor cell as above.
ProbeSelection selectProbes(std::span<const CandidateService> services,
                            std::span<const CaptureSight> sights, const FloorInSight& inSight,
                            std::span<const std::size_t> captureCells,
                            std::span<const FloorSample> samples, const WalkableFloor& floor,
                            const SelectionOptions& options, const KeptFloor& kept = {});

}  // namespace probeproxy
