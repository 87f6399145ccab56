#pragma once
// Boxes around what a probe sees: the `obb` and `aabb` methods' proxies.

#include "core/proxy/proxy_shape.h"

#include <glm/vec3.hpp>

#include <span>

namespace probeproxy {

// A small-volume oriented box around the points: CGAL's oriented_bounding_box (an optimizer
// with a fixed seed, so the same input gives the same box), then polished: each box axis is
// also tried snapped to the nearest hull facet normal with the smallest rectangle around the
// points across it (exact for box-shaped rooms), and the smallest volume wins. Every point is
// inside. The rotation is canonical: among the 24 ways to name a box's axes, the proper
// rotation closest to the identity, with w >= 0; within 1e-9 rad of the identity it is exactly
// the identity (then methodId says "aabb"). Points on one plane give a box of zero thickness,
// on one line a box along it, one point a box of zero size. FitError when there are no points
// or a coordinate is not finite.
BoxShape orientedBoxFit(std::span<const glm::dvec3> pointsMeters);

// The oriented box that stands upright (one axis along +z) with the smallest footprint around
// the points: CGAL's rotating calipers on their plan, no optimizer. Level rooms are upright,
// so where thousands of coarse proxies are fitted (layout candidates) this is the box that
// matters at a twentieth of the cost. Canonical rotation and FitError as above.
BoxShape uprightBoxFit(std::span<const glm::dvec3> pointsMeters);

// The world-axis box around the points (identity rotation). FitError as above.
BoxShape axisAlignedBoxFit(std::span<const glm::dvec3> pointsMeters);

}  // namespace probeproxy
