#pragma once
// Whether a proxy is a box, so that engines which take only a box (engine_probes.h) can get
// the kept proxy itself rather than the best `aabb`/`obb` candidate (a kept
// `convex_6` that is exactly the room went out as an `aabb` 35 degrees worse).
//
// A convex is a box when it has six planes in three opposite pairs at right angles and the box
// spanned by its corners lies within kBoxCornerToleranceMeters of it: every corner of each is
// that close to a corner of the other. Both are the convex hulls of their 8 corners, so the
// Hausdorff distance between the two volumes is at most that too, and the box's error is the
// kept proxy's measured error to within what a shift of 1 um can change.

#include "core/proxy/proxy_shape.h"

#include <optional>

namespace probeproxy {

// 1 um: below a float32's spacing at 10 m (2^-20 m ~ 0.95 um), the precision an engine stores
// a transform in, so an engine cannot tell the two apart.
inline constexpr double kBoxCornerToleranceMeters = 1e-6;

// The box a six-plane convex is, or nothing. Its rotation is exactly the identity (an `aabb`)
// when the axis-aligned box through the corners is within the tolerance too; otherwise the
// box's own x, y, z axes are the plane pairs closest to the world's x, y, z (right-handed).
std::optional<BoxShape> boxOfConvex(const ConvexProxy& convex);

// The kept shape as a box: a BoxShape itself, a convex that is a box, or nothing.
std::optional<BoxShape> keptBox(const ProxyShape& shape);

}  // namespace probeproxy
