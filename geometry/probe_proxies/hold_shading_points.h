#pragma once
// A proxy must hold every point it is looked up from: a lookup from a shading point outside
// the proxy is a miss (180 degrees in every figure). The walls that model a room best can stand
// short of floor the probe serves: the room box's axis rays stop at an alcove's mouth or a step
// down (a warfare probe's room box modelled its floor at 1.6 degrees median but missed one
// reflection in fifty, and lost to a sphere at 10.5), and an inner wall of a concave room, a
// starting plane of the simplification, cuts off the floor round the corner. Grown just enough
// to hold that floor, the same walls keep modelling the room everywhere else.

#include "core/proxy/convex_proxy.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/evaluation/reflection_sample.h"

#include <span>
#include <vector>

namespace probeproxy {

// The axis-aligned box grown, face by face, to hold the shading point of every sample whose
// reflection the capture point sees.
BoxShape holdingShadingPoints(BoxShape box, std::span<const ReflectionSample> samples);

// Each plane moved out along its normal, as little as holds those points.
std::vector<ProxyPlane> holdingShadingPoints(std::vector<ProxyPlane> planes,
                                             std::span<const ReflectionSample> samples);

}  // namespace probeproxy
