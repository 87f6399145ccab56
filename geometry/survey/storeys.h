#pragma once
// Storeys of a walkable floor, for one error map each: where some grid column holds floor
// above floor (a U-corridor's upper level over its lower one), the floor is split at heights
// between the stacked cells; otherwise it is one storey.

#include "geometry/floor/walkable_floor.h"

#include <vector>

namespace probeproxy {

// storey[i] of floor.cells[i], 0 = lowest; the count is max(storey) + 1.
std::vector<int> floorStoreys(const WalkableFloor& floor);

}  // namespace probeproxy
