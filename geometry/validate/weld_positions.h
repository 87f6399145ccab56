#pragma once
// Welding positions that an exporter split: OBJ and glTF write a corner once per face (for
// flat normals or UV seams), so a closed cube arrives as six separate quads. Checks that ask
// "is this closed?" must first treat corners at the same place as one vertex.

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace probeproxy {

// For every position, the index of the vertex it welds to: the lowest-indexed earlier position
// within `toleranceMeters` (Euclidean), or its own index. A representative always maps to
// itself, so the result can be used directly as a vertex index. `toleranceMeters` = 0 welds
// exact duplicates only. Greedy in index order, deterministic; expected time O(n).
std::vector<std::uint32_t> weldPositions(std::span<const glm::dvec3> positionsMeters,
                                         double toleranceMeters);

}  // namespace probeproxy
