#pragma once
// Where to fan a convex polygon (a proxy's facet) from. A fan from a corner that lies in line
// with two others (where a third plane only just cuts an edge: a facet of bloodprison's
// layout) has a triangle of no area, which validate's proxy_degenerate_face and engines'
// importers reject; fanned from another corner the same polygon has none. And a facet whose
// corners are merged within rounding (polytopeFromPlanes) is not quite planar: a fan across
// the wrong diagonal folds inwards (bloodprison's layout: a 1 cm facet of a 178 m proxy, its
// corners 0.24 mm off its plane, folded in by 1.2 deg, validate's proxy_concave_edge), across
// the other it folds outwards, as a convex proxy may.

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace probeproxy {

// The triangle's smallest height: twice its area over its longest side (what validate's
// proxy_degenerate_face compares with 1e-6 of the mesh's size).
double smallestHeight(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c);

// `corners` counter-clockwise seen from outside. Of the corners whose fan folds inwards least
// (not at all, for a planar or convex polygon, up to rounding: of the facet's size, or of its
// corners written as floats), the one whose fan's lowest triangle (smallestHeight) is highest;
// the first such corner on ties, so the fan depends on the polygon only. 0 for a triangle.
std::size_t fanApex(std::span<const glm::dvec3> corners);

}  // namespace probeproxy
