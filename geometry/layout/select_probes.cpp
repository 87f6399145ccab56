#include "geometry/layout/select_probes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <queue>

namespace probeproxy {

namespace {

// What one candidate holds of the floor, over a window of cells a row: in each row from the
// first it holds in sight and sees a sample of to the last (cells are numbered row by row and a
// row's are contiguous): per cell 0 where it does not, else 1 + the samples of the cell it
// serves within the tolerance. One byte a cell of its windows: a candidate at an open level's
// crossroads sees down two streets, a few rows whole and a few cells of every other row, where
// one window from its first cell to its last held every row between them (a byte a cell of the
// level, for each of thousands of candidates).
class CandidateCells {
 public:
  // `held`: ascending; `rowOf`: every floor cell's row.
  void hold(std::span<const std::size_t> held, std::span<const int> rowOf) {
    if (held.empty()) return;
    firstRow_ = rowOf[held.front()];
    rows_.assign(static_cast<std::size_t>(rowOf[held.back()] - firstRow_ + 1), RowWindow{});
    for (std::size_t k = 0; k < held.size();) {
      std::size_t last = k;
      while (last + 1 < held.size() && rowOf[held[last + 1]] == rowOf[held[k]]) ++last;
      RowWindow& w = rows_[static_cast<std::size_t>(rowOf[held[k]] - firstRow_)];
      w.firstCell = held[k];
      w.cells = static_cast<std::uint32_t>(held[last] - held[k] + 1);
      w.offset = code_.size();
      code_.resize(code_.size() + w.cells, 0);
      for (std::size_t j = k; j <= last; ++j) code_[w.offset + (held[j] - held[k])] = 1;
      k = last + 1;
    }
  }
  std::uint8_t at(std::size_t cell, int row) const {
    if (row < firstRow_ || static_cast<std::size_t>(row - firstRow_) >= rows_.size()) return 0;
    const RowWindow& w = rows_[static_cast<std::size_t>(row - firstRow_)];
    return cell >= w.firstCell && cell - w.firstCell < w.cells
               ? code_[w.offset + cell - w.firstCell]
               : 0;
  }
  // Counts one more served sample of a held cell.
  void serve(std::size_t cell, int row) {
    if (at(cell, row) == 0) return;
    const RowWindow& w = rows_[static_cast<std::size_t>(row - firstRow_)];
    ++code_[w.offset + cell - w.firstCell];
  }
  // Calls f(cell, code) for every cell of the windows.
  template <class F>
  void forEachCell(F&& f) const {
    for (const RowWindow& w : rows_)
      for (std::uint32_t k = 0; k < w.cells; ++k) f(w.firstCell + k, code_[w.offset + k]);
  }

 private:
  struct RowWindow {
    std::size_t firstCell = 0, offset = 0;
    std::uint32_t cells = 0;  // 0: none of the row held
  };
  int firstRow_ = 0;
  std::vector<RowWindow> rows_;
  std::vector<std::uint8_t> code_;
};

// Per candidate, the share of each floor cell's samples it serves within the tolerance (0 out of
// its sight) and the cells it sees a sample of, of the floor it holds in sight; per cell, the
// best share any candidate serves.
struct CellSets {
  std::vector<CandidateCells> candidates;
  std::vector<int> samplesPerCell;
  std::vector<float> best;
  std::vector<int> rowOf;  // per floor cell

  bool sees(std::size_t c, std::size_t cell) const { return code(c, cell) != 0; }
  float share(std::size_t c, std::size_t cell) const { return shareOf(code(c, cell), cell); }
  std::uint8_t code(std::size_t c, std::size_t cell) const {
    return candidates[c].at(cell, rowOf[cell]);
  }
  float shareOf(std::uint8_t code, std::size_t cell) const {
    return code == 0 ? 0.0f
                     : static_cast<float>(code - 1) / static_cast<float>(samplesPerCell[cell]);
  }
  // How well candidate c serves a cell against the best any candidate does there: a strip of a
  // range is judged by this (floor_rectangles.h), and floor nobody serves is anybody's who sees
  // it.
  double score(std::size_t c, std::size_t cell) const {
    if (!sees(c, cell)) return 0.0;
    return best[cell] > 0.0f ? share(c, cell) / best[cell] : 1.0;
  }
};

CellSets cellSets(std::span<const CandidateService> services, std::span<const CaptureSight> sights,
                  const FloorInSight& inSight, std::span<const FloorSample> samples,
                  std::span<const FloorCell> cells) {
  CellSets sets;
  sets.samplesPerCell.assign(cells.size(), 0);
  for (const FloorSample& s : samples) ++sets.samplesPerCell[s.cell];
  for (const FloorCell& cell : cells) sets.rowOf.push_back(cell.row);
  sets.candidates.resize(services.size());
  // A capture point's fit regions share its sight: the cells it holds are found once for
  // them all, each asked of the level without keeping the answer (a capture point sees the sky
  // over most of an open level, and kept, the answers took a byte a cell of the level for each
  // capture point; the selection's own questions, about the cells near each, are kept).
  std::map<std::size_t, std::vector<std::size_t>> byCapture;
  for (std::size_t c = 0; c < services.size(); ++c) byCapture[services[c].capture].push_back(c);
  const std::vector<std::pair<std::size_t, std::vector<std::size_t>>> groups(byCapture.begin(),
                                                                             byCapture.end());
  tbb::parallel_for(std::size_t{0}, groups.size(), [&](std::size_t g) {
    const std::size_t capture = groups[g].first;
    std::vector<std::size_t> held;  // cells it sees a sample of and holds in sight, ascending
    forEachIndex(sights[capture].seen, [&](std::uint32_t i) {
      const std::size_t cell = samples[i].cell;
      if ((held.empty() || held.back() != cell) && inSight.inSightOnce(capture, cell))
        held.push_back(cell);
    });
    for (std::size_t c : groups[g].second) {
      CandidateCells& windows = sets.candidates[c];
      windows.hold(held, sets.rowOf);
      forEachIndex(services[c].served, [&](std::uint32_t i) {
        const std::size_t cell = samples[i].cell;
        windows.serve(cell, sets.rowOf[cell]);
      });
    }
  });
  sets.best.assign(cells.size(), 0.0f);
  for (const CandidateCells& windows : sets.candidates)
    windows.forEachCell([&](std::size_t cell, std::uint8_t code) {
      sets.best[cell] = std::max(sets.best[cell], sets.shareOf(code, cell));
    });
  return sets;
}

// A range's floor and its gap are no other range's: as far down as its inner range reaches (a
// step under its floor), else a range or fill on a stair a step lower overlaps it (bloodprison:
// two ranges 0.3 m apart, one's plan inside the other's; darkzone: a fill).
void claimWithGap(const FloorColumns& columns, const FloorRect& rect, int gapCells,
                  std::vector<char>& claimed) {
  columns.forEachUnderInnerRange(widened(rect, gapCells),
                                 [&](std::size_t cell) { claimed[cell] = 1; });
}

struct Cover {
  const FloorColumns& columns;
  std::span<const CandidateService> services;
  std::span<const std::size_t> captureCells;
  const SelectionOptions& options;
  std::vector<char> claimed;  // inside a chosen range or its gap
  ProbeSelection selection;

  // Floor out of the candidate's sight is not acceptable (cellSets): a strip may hold a tenth
  // of it at most. Ending the growth there too gave the same layouts within a probe a map.
  FloorRect rectOf(std::size_t c, const std::function<double(std::size_t)>& acceptable,
                   double acceptedShare) const {
    return growFloorRect(
        columns, captureCells[services[c].capture], acceptable,
        [&](std::size_t cell) { return claimed[cell] != 0; }, acceptedShare);
  }

  double gainOf(const FloorRect& rect, const std::function<double(std::size_t)>& worth) const {
    double gain = 0.0;
    if (!rect.empty()) columns.forEachIn(rect, [&](std::size_t cell) { gain += worth(cell); });
    return gain;
  }

  void choose(std::size_t c, const FloorRect& rect) {
    selection.chosen.push_back(c);
    selection.ranges.push_back(rect);
    claimWithGap(columns, rect, options.gapCells, claimed);
  }

  // Greedy with lazy gains: claims only grow, so a candidate's rectangle and gain only shrink,
  // and one whose recomputed gain still tops the queue is the best.
  // `acceptedShare`: of a strip (floor_rectangles.h).
  void greedy(const std::function<double(std::size_t, std::size_t)>& acceptable,
              const std::function<double(std::size_t, std::size_t)>& worth, double acceptedShare,
              double minGain) {
    const auto evaluate = [&](std::size_t c, FloorRect& rect) {
      rect = rectOf(
          c, [&](std::size_t cell) { return acceptable(c, cell); }, acceptedShare);
      return gainOf(rect, [&](std::size_t cell) { return worth(c, cell); });
    };
    std::vector<double> gains(services.size(), 0.0);
    tbb::parallel_for(std::size_t{0}, services.size(), [&](std::size_t c) {
      FloorRect rect;
      gains[c] = evaluate(c, rect);
    });
    using Entry = std::pair<double, std::size_t>;  // gain, candidate
    const auto lower = [](const Entry& a, const Entry& b) {
      return a.first < b.first || (a.first == b.first && a.second > b.second);
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(lower)> queue(lower);
    for (std::size_t c = 0; c < services.size(); ++c)
      if (gains[c] >= minGain) queue.push({gains[c], c});
    while (!queue.empty() &&
           (options.maxProbes == 0 || selection.chosen.size() < options.maxProbes)) {
      const Entry top = queue.top();
      queue.pop();
      FloorRect rect;
      const double gain = evaluate(top.second, rect);
      if (gain < minGain) continue;
      if (!queue.empty() && lower(Entry{gain, top.second}, queue.top())) {
        queue.push({gain, top.second});
        continue;
      }
      choose(top.second, rect);
    }
  }
};

bool sameStorey(const FloorRect& a, const FloorRect& b) {
  return std::abs(a.floorMeters - b.floorMeters) <
         kInfluenceBelowFloorMeters + kInfluenceHeadRoomMeters;
}

bool rangesOverlap(const FloorRect& a, const FloorRect& b) {
  return a.column0 <= b.column1 && b.column0 <= a.column1 && a.row0 <= b.row1 && b.row0 <= a.row1 &&
         sameStorey(a, b);
}

// Whether two inner ranges keep the blend band between them. Ranges that touch hand the floor
// from one probe's 100% to the other's at once (Lagarde's inner range): the lighting pops.
bool keepsGap(const FloorRect& a, const FloorRect& b, int gapCells) {
  return !rangesOverlap(widened(a, gapCells), b);
}

// How many cells the rectangle must stretch, along both axes, for its band to reach a cell.
int stretchNeeded(const FloorRect& rect, const FloorCell& cell, int gapCells) {
  const int dc =
      std::max({0, rect.column0 - gapCells - cell.column, cell.column - rect.column1 - gapCells});
  const int dr = std::max({0, rect.row0 - gapCells - cell.row, cell.row - rect.row1 - gapCells});
  return dc + dr;
}

FloorRect stretchedToward(FloorRect rect, const FloorCell& cell, int gapCells) {
  rect.column0 = std::min(rect.column0, cell.column + gapCells);
  rect.column1 = std::max(rect.column1, cell.column - gapCells);
  rect.row0 = std::min(rect.row0, cell.row + gapCells);
  rect.row1 = std::max(rect.row1, cell.row - gapCells);
  return rect;
}

FloorRect boundingUnion(const FloorRect& a, const FloorRect& b) {
  FloorRect u = a;
  u.column0 = std::min(a.column0, b.column0), u.column1 = std::max(a.column1, b.column1);
  u.row0 = std::min(a.row0, b.row0), u.row1 = std::max(a.row1, b.row1);
  return u;
}

// Whether range i's probe holds in sight all the floor `grown` adds to its range.
bool gainsOnlyFloorInSight(const FloorColumns& columns, std::span<const CandidateService> services,
                           const FloorInSight& inSight, const ProbeSelection& selection,
                           std::size_t i, const FloorRect& grown) {
  bool all = true;
  const std::size_t capture = services[selection.chosen[i]].capture;
  columns.forEachIn(grown, [&](std::size_t cell) {
    all = all && (selection.ranges[i].holds(columns.floor().cells[cell]) ||
                  inSight.inSight(capture, cell));
  });
  return all;
}

// The refining pass: a probe whose whole range a neighbour can take over, serving (in the
// accepted share) the floor its range would gain and keeping the band from every third range, is
// dropped, the last taken (the smallest gain) first. Greedy order leaves such probes where the
// first big range blocked a second one's growth (the L-room's corner, between its two arms).
void dropAbsorbed(const FloorColumns& columns, const CellSets& sets,
                  std::span<const CandidateService> services, const FloorInSight& inSight,
                  double acceptedShare, int gapCells, ProbeSelection& selection) {
  for (std::size_t p = selection.chosen.size(); p-- > 0;) {
    for (std::size_t q = 0; q < selection.chosen.size(); ++q) {
      if (q == p || !sameStorey(selection.ranges[p], selection.ranges[q])) continue;
      const FloorRect merged = boundingUnion(selection.ranges[q], selection.ranges[p]);
      bool clear = true;
      for (std::size_t j = 0; j < selection.ranges.size() && clear; ++j)
        clear = j == p || j == q || keepsGap(merged, selection.ranges[j], gapCells);
      if (!clear) continue;
      double gained = 0.0, served = 0.0;
      columns.forEachIn(merged, [&](std::size_t cell) {
        if (selection.ranges[q].holds(columns.floor().cells[cell])) return;
        const double area = columns.floor().cells[cell].areaSquareMeters;
        gained += area;
        served += sets.share(selection.chosen[q], cell) * area;
      });
      if (served < acceptedShare * gained ||
          !gainsOnlyFloorInSight(columns, services, inSight, selection, q, merged))
        continue;
      selection.ranges[q] = merged;
      selection.chosen.erase(selection.chosen.begin() + static_cast<std::ptrdiff_t>(p));
      selection.ranges.erase(selection.ranges.begin() + static_cast<std::ptrdiff_t>(p));
      break;
    }
  }
}

// "Model no more than the level needs": when one candidate alone serves, within the tolerance,
// nearly as much of the floor as the whole cover does (within `slack` of the floor's area) and
// at least `acceptedShare` of it, and the floor is one storey its range can hold, one probe is
// the layout. A box room with a few
// props (the hangar) has floor near the props that no proxy serves whole; the cover's small
// probes there were chosen on coarse candidates and do not deliver once built and blended.
std::optional<ProbeSelection> oneProbeServesAsMuch(
    const FloorColumns& columns, const CellSets& sets, std::span<const CandidateService> services,
    const FloorInSight& inSight, const ProbeSelection& cover, double slack, double acceptedShare) {
  const WalkableFloor& floor = columns.floor();
  if (cover.chosen.size() < 2 || floor.cells.empty()) return std::nullopt;
  FloorRect all{floor.cells[0].column, floor.cells[0].column, floor.cells[0].row,
                floor.cells[0].row, floor.cells[0].pointMeters.z};
  double lowest = floor.cells[0].pointMeters.z;
  for (const FloorCell& c : floor.cells) {
    all.column0 = std::min(all.column0, c.column), all.column1 = std::max(all.column1, c.column);
    all.row0 = std::min(all.row0, c.row), all.row1 = std::max(all.row1, c.row);
    lowest = std::min(lowest, c.pointMeters.z);
  }
  all.floorMeters = lowest;
  double area = 0.0, coverServed = 0.0;
  for (std::size_t cell = 0; cell < floor.cells.size(); ++cell) {
    if (!all.holds(floor.cells[cell])) return std::nullopt;  // more than one storey
    const double a = floor.cells[cell].areaSquareMeters;
    area += a;
    float coverShare = 0.0f;
    for (std::size_t c : cover.chosen) coverShare = std::max(coverShare, sets.share(c, cell));
    coverServed += coverShare * a;
  }
  const std::size_t candidates = sets.candidates.size();
  std::size_t best = candidates;
  double bestServed = 0.0;
  for (std::size_t c = 0; c < candidates; ++c) {
    double served = 0.0;
    for (std::size_t cell = 0; cell < floor.cells.size(); ++cell)
      served += sets.share(c, cell) * floor.cells[cell].areaSquareMeters;
    if (served > bestServed) best = c, bestServed = served;
  }
  if (best == candidates || bestServed < coverServed - slack * area ||
      bestServed < acceptedShare * area)
    return std::nullopt;
  for (std::size_t cell = 0; cell < floor.cells.size(); ++cell)
    if (!inSight.inSight(services[best].capture, cell)) return std::nullopt;
  return ProbeSelection{{best}, {all}, {}};
}

// Whether some range's band (or a kept volume) reaches the floor cell: its box's, so floor a
// step under a range (a stair between the range's cells) is not left to a probe of its own.
bool banded(const WalkableFloor& floor, std::size_t cell, int gapCells,
            std::span<const char> keptCovered, std::span<const FloorRect> ranges) {
  if (!keptCovered.empty() && keptCovered[cell]) return true;
  return std::any_of(ranges.begin(), ranges.end(), [&](const FloorRect& r) {
    return widened(r, gapCells).underInnerRange(floor.cells[cell]);
  });
}

// Floor that no range's band reaches (crumbs too small to be worth a probe, floor between
// ranges wider than the band): the range on its storey that needs the least stretch takes it,
// where the stretched range keeps the band from every other and its probe holds in sight all
// the floor it gains.
void coverLeftovers(const FloorColumns& columns, std::span<const CandidateService> services,
                    const FloorInSight& inSight, int gapCells, std::span<const char> keptCovered,
                    ProbeSelection& selection) {
  const WalkableFloor& floor = columns.floor();
  std::vector<FloorRect>& ranges = selection.ranges;
  for (std::size_t cell = 0; cell < floor.cells.size(); ++cell) {
    if (banded(floor, cell, gapCells, keptCovered, ranges)) continue;
    const FloorCell& at = floor.cells[cell];
    std::vector<std::pair<int, std::size_t>> order;  // stretch, range
    for (std::size_t i = 0; i < ranges.size(); ++i) {
      FloorRect storey = ranges[i];
      storey.column0 = storey.column1 = at.column, storey.row0 = storey.row1 = at.row;
      if (storey.holds(at)) order.push_back({stretchNeeded(ranges[i], at, gapCells), i});
    }
    std::sort(order.begin(), order.end());
    for (const auto& [stretch, i] : order) {
      const FloorRect stretched = stretchedToward(ranges[i], at, gapCells);
      bool clear = true;
      for (std::size_t j = 0; j < ranges.size() && clear; ++j)
        clear = j == i || keepsGap(stretched, ranges[j], gapCells);
      if (!clear || !gainsOnlyFloorInSight(columns, services, inSight, selection, i, stretched))
        continue;
      ranges[i] = stretched;
      break;
    }
  }
}

// Floor in one range's band and no other's, that its candidate sees, joins its inner range
// when a strip can (keeping the gap): Lagarde's blend gives it to that probe whole either way,
// but at the band's far side its weight tends to 0, and where a second band begins there the
// shares swing within centimetres (a range that stops short of a wall, beside a neighbour's).
void growIntoOwnBands(const FloorColumns& columns, const CellSets& sets, int gapCells,
                      std::span<const char> keptCovered, ProbeSelection& selection) {
  std::vector<FloorRect>& ranges = selection.ranges;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const std::size_t c = selection.chosen[i];
    const auto othersBand = [&](std::size_t cell) {
      if (!keptCovered.empty() && keptCovered[cell]) return true;
      for (std::size_t j = 0; j < ranges.size(); ++j)
        if (j != i && widened(ranges[j], gapCells).underInnerRange(columns.floor().cells[cell]))
          return true;
      return false;
    };
    const FloorRect band = widened(ranges[i], gapCells);
    ranges[i] = grownFloorRect(
        columns, ranges[i],
        [&](std::size_t cell) {
          return sets.sees(c, cell) && band.holds(columns.floor().cells[cell]);
        },
        othersBand, 1.0);
  }
}

// What coverLeftovers could not give to a range: rectangles grown over it, each a band clear of
// every range and fill before it. Every floor cell is then in some range's band.
std::vector<FloorRect> fillsForTheRest(const FloorColumns& columns, int gapCells,
                                       std::span<const char> keptCovered,
                                       std::span<const FloorRect> ranges) {
  const WalkableFloor& floor = columns.floor();
  // A fill grows over floor no band reaches, and keeps the band from every fill before it.
  std::vector<char> claimed(floor.cells.size(), 0);
  for (std::size_t cell = 0; cell < floor.cells.size(); ++cell)
    claimed[cell] = banded(floor, cell, gapCells, keptCovered, ranges);
  std::vector<FloorRect> fills;
  for (std::size_t cell = 0; cell < floor.cells.size(); ++cell) {
    if (claimed[cell]) continue;
    const FloorRect fill = growFloorRect(
        columns, cell, [](std::size_t) { return true; },
        [&](std::size_t c) { return claimed[c] != 0; }, 1.0);
    fills.push_back(fill);
    claimWithGap(columns, fill, gapCells, claimed);
  }
  return fills;
}

}  // namespace

ProbeSelection selectProbes(std::span<const CandidateService> services,
                            std::span<const CaptureSight> sights, const FloorInSight& inSight,
                            std::span<const std::size_t> captureCells,
                            std::span<const FloorSample> samples, const WalkableFloor& floor,
                            const SelectionOptions& o, const KeptFloor& kept) {
  const FloorColumns columns(floor);
  const CellSets sets = cellSets(services, sights, inSight, samples, floor.cells);
  Cover cover{columns, services, captureCells, o, std::vector<char>(floor.cells.size(), 0), {}};
  // Floor the kept probes already serve is worth nothing to a new probe, but a new range may
  // take it in on its way to the floor they fail (where it serves it too, as ranges grow only
  // over floor their candidate serves): closed, it would leave no room round the pillars.
  const auto area = [&](std::size_t cell) {
    return !kept.served.empty() && kept.served[cell] ? 0.0 : floor.cells[cell].areaSquareMeters;
  };
  const double minGain = std::max(o.minGainSquareMeters, o.minGainShare * floor.areaSquareMeters());
  // Served floor first, in ranges that serve it as well as any candidate can, then in looser
  // ones; floor nobody serves goes to those who see it, worth a quarter as much.
  for (const SelectionOptions::CoverPass& pass : o.passes) {
    cover.greedy([&](std::size_t c, std::size_t cell) { return sets.score(c, cell); },
                 [&](std::size_t c, std::size_t cell) {
                   const double unserved = sets.best[cell] == 0.0f && sets.sees(c, cell);
                   return (sets.share(c, cell) + 0.25 * unserved) * area(cell);
                 },
                 pass.acceptedShare, std::max(minGain, pass.minGainSquareMeters));
  }
  // What is left outside every range and band: the candidates that see it, the ones that serve
  // it first.
  cover.greedy([&](std::size_t c, std::size_t cell) { return sets.sees(c, cell) ? 1.0 : 0.0; },
               [&](std::size_t c, std::size_t cell) {
                 return sets.sees(c, cell) ? (0.25 + sets.share(c, cell)) * area(cell) : 0.0;
               },
               o.acceptedShare, minGain);
  dropAbsorbed(columns, sets, services, inSight, o.acceptedShare, o.gapCells, cover.selection);
  if (kept.served.empty()) {
    if (const auto one = oneProbeServesAsMuch(columns, sets, services, inSight, cover.selection,
                                              o.oneProbeSlack, o.acceptedShare))
      cover.selection = *one;
  }
  coverLeftovers(columns, services, inSight, o.gapCells, kept.covered, cover.selection);
  growIntoOwnBands(columns, sets, o.gapCells, kept.covered, cover.selection);
  cover.selection.fills =
      fillsForTheRest(columns, o.gapCells, kept.covered, cover.selection.ranges);
  return cover.selection;
}

}  // namespace probeproxy
