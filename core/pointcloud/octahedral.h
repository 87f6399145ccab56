#pragma once
// The octahedral map of directions (world frame): the unit sphere projected onto the
// octahedron |x| + |y| + |z| = 1, its lower half folded out over the square's corners, so the
// whole sphere is one square image (Hodgman's "Imperfect Environment Maps" uses it for its
// point-cloud splats).
//   uv in [0, 1]^2, u right, v down; +Z at the centre, -Z at the four corners.
// Texel (col, row) of an N x N map has its centre at ((col + 0.5) / N, (row + 0.5) / N).

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace probeproxy {

// Any non-zero direction (need not be unit); a zero one gives the centre.
glm::vec2 octahedralUvFromDirection(glm::vec3 direction);

// The unit direction at uv (the inverse of the above on [0, 1]^2).
glm::vec3 directionFromOctahedralUv(glm::vec2 uv);

// Texel (col, row) of an N x N map, with col and row up to N outside it, folded back to the
// texel that borders it on the sphere (across an edge of the square the map continues
// mirrored: (-1, r) is (0, N - 1 - r)). For filters that cross the square's edges.
void wrapOctahedralTexel(int& col, int& row, int size);

}  // namespace probeproxy
