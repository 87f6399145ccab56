#pragma once
// The synthetic lookups the cost figures are measured on: one proxy per method and rays from
// shading points inside it. bench_lookup (ns per lookup) and the callgrind driver
// (instructions per lookup) both use these, so the two figures come from the same rays.

#include "core/parallax/prepared_proxy.h"

#include <cstdint>
#include <string>
#include <vector>

namespace probeproxy {

struct LookupWorkload {
  std::string name;     // "infinite", "cheap_k", "sphere", "aabb", "obb", "convex_<k>"
  PreparedProxy proxy;  // capture point (0.3, -0.2, 1.2) m
  // Shading points (world metres, all inside the proxy) and unit reflection directions.
  std::vector<float> x, y, z, rx, ry, rz;
};

// `rays` rays from a fixed seed per name; the first n rays are the same for any rays >= n.
// Shapes: sphere = ellipsoid with radii (5, 4, 3) m turned 30 degrees about Z; aabb = box with
// half-extents (5, 4, 1.5) m; obb = the same box turned 30 degrees; convex_<k> (k >= 4) = k
// planes 3 m from (0, 0, 1.2) whose normals spread evenly over the sphere (Fibonacci).
// Throws std::invalid_argument on another name.
LookupWorkload makeLookupWorkload(const std::string& name, std::size_t rays);

// The workload name for a method: its methodName, or convex_<planes> for convex.
std::string costWorkloadName(Method method, int planes);

// The rows of the cost table: infinite cheap_k sphere aabb obb convex_6 convex_20.
const std::vector<std::string>& costTableWorkloads();

// Where lookups go, one array per output (not shared with the inputs).
struct LookupOutputs {
  explicit LookupOutputs(std::size_t n) : dx(n), dy(n), dz(n), miss(n) {}
  std::vector<float> dx, dy, dz;
  std::vector<std::uint8_t> miss;
};

// Every ray of the workload through lookupScalar (one call per ray, the seeds' shader ports)
// or through one lookupBatch call. `out` must hold as many entries as the workload has rays.
void runScalarLookups(const LookupWorkload& w, LookupOutputs& out);
void runBatchedLookups(const LookupWorkload& w, LookupOutputs& out);

}  // namespace probeproxy
