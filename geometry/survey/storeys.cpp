#include "geometry/survey/storeys.h"

#include <algorithm>
#include <map>

namespace probeproxy {

std::vector<int> floorStoreys(const WalkableFloor& floor) {
  // Cells come by row, column, then height: the columns' stacks are runs of equal (row, col).
  std::map<int, std::vector<double>> cutsAbove;  // stack level k -> midpoints to level k + 1
  for (std::size_t i = 0; i < floor.cells.size();) {
    std::size_t end = i + 1;
    while (end < floor.cells.size() && floor.cells[end].row == floor.cells[i].row &&
           floor.cells[end].column == floor.cells[i].column)
      ++end;
    for (std::size_t k = i; k + 1 < end; ++k)
      cutsAbove[static_cast<int>(k - i)].push_back(
          0.5 * (floor.cells[k].pointMeters.z + floor.cells[k + 1].pointMeters.z));
    i = end;
  }
  // One cut per stack level, the median of its columns' midpoints: robust to a few odd
  // columns (a stair under a landing).
  std::vector<double> cuts;
  for (auto& [level, mids] : cutsAbove) {
    std::nth_element(mids.begin(), mids.begin() + mids.size() / 2, mids.end());
    const double cut = mids[mids.size() / 2];
    if (cuts.empty() || cut > cuts.back()) cuts.push_back(cut);
  }
  std::vector<int> storey(floor.cells.size(), 0);
  for (std::size_t i = 0; i < floor.cells.size(); ++i) {
    const double z = floor.cells[i].pointMeters.z;
    storey[i] = static_cast<int>(std::upper_bound(cuts.begin(), cuts.end(), z) - cuts.begin());
  }
  return storey;
}

}  // namespace probeproxy
