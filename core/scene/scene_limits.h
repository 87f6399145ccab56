#pragma once
// The numbers a scene may hold (README "Scene file", "Limits"). They are checked where the
// scene and its level are read, so that nothing past the readers meets a number Embree, the
// weight grids or an allocation cannot take.

#include <cstddef>

namespace probeproxy {

// Every position (probe, influence, level vertex) within this distance of the origin on each
// axis, every half-extent and radius at most this, in metres after meters_per_unit. 100 km is
// far past any game level, and float positions there still resolve about 8 mm.
inline constexpr double kMaxSceneMeters = 1e5;
inline constexpr double kMinMetersPerUnit = 1e-6;
inline constexpr double kMaxMetersPerUnit = 1e6;

// Triangles over the whole level. The largest Quake 3 maps hold about 10^5; at 5 * 10^7 the
// level and its Embree scene already take several GiB.
inline constexpr std::size_t kMaxLevelTriangles = 50'000'000;

}  // namespace probeproxy
