#pragma once
// Where to fan a convex polygon (a proxy's facet) from. A fan from a corner that lies in line
// with two others (where a third plane only just cuts an edge: a facet of bloodprison's
// layout) has a triangle of no area, which validate's proxy_degenerate_face and engines'
// importers reject; fanned from another corner the same polygon has none.

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace probeproxy {

// The triangle's smallest height: twice its area over its longest side (what validate's
// proxy_degenerate_face compares with 1e-6 of the mesh's size).
double smallestHeight(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c);

// The corner whose fan's lowest triangle (smallestHeight) is highest;
// the first such corner on ties, so the fan depends on the polygon only. 0 for a triangle.
std::size_t fanApex(std::span<const glm::dvec3> corners);

}  // namespace probeproxy
