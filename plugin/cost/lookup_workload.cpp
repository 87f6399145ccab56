#include "plugin/cost/lookup_workload.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <random>
#include <stdexcept>

namespace probeproxy {

namespace {

constexpr double kPi = 3.14159265358979323846;

ConvexProxy fibonacciPolytope(int planes, glm::dvec3 centerMeters, double inradiusMeters) {
  ConvexProxy proxy;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < planes; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / planes;
    const double ring = std::sqrt(1.0 - z * z);
    const glm::dvec3 n(ring * std::cos(golden * i), ring * std::sin(golden * i), z);
    proxy.planes.push_back({n, glm::dot(n, centerMeters) + inradiusMeters});
  }
  return proxy;
}

ProxyShape shapeFor(const std::string& name) {
  const glm::dquat tilt = glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 0, 1));
  if (name == "infinite") return InfiniteShape{};
  if (name == "cheap_k") return CheapKShape{0.3};
  if (name == "sphere") return SphereShape{{0, 0, 1.2}, {5, 4, 3}, tilt};
  if (name == "aabb") return BoxShape{{0, 0, 1.5}, {5, 4, 1.5}};
  if (name == "obb") return BoxShape{{0, 0, 1.5}, {5, 4, 1.5}, tilt};
  if (name.rfind("convex_", 0) == 0) {
    const std::string k = name.substr(7);
    if (!k.empty() && k.size() <= 4 && k.find_first_not_of("0123456789") == std::string::npos &&
        std::stoi(k) >= 4) {
      return fibonacciPolytope(std::stoi(k), {0, 0, 1.2}, 3.0);
    }
  }
  throw std::invalid_argument("lookup workload '" + name +
                              "': expected infinite, cheap_k, sphere, aabb, obb or convex_<k>, "
                              "k from 4 to 9999");
}

}  // namespace

LookupWorkload makeLookupWorkload(const std::string& name, std::size_t rays) {
  LookupWorkload w{name, prepareProxy(shapeFor(name), {0.3, -0.2, 1.2}), {}, {}, {}, {}, {}, {}};
  std::uint32_t seed = 2166136261u;  // FNV-1a of the name: fixed on every platform
  for (const char c : name) seed = (seed ^ static_cast<unsigned char>(c)) * 16777619u;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::normal_distribution<float> g;
  for (std::size_t i = 0; i < rays; ++i) {
    // Within 0.855 m of (0, 0, 1.2) along each axis (1.48 m away at most): inside every shape.
    w.x.push_back(0.855f * u(rng));
    w.y.push_back(0.855f * u(rng));
    w.z.push_back(1.2f + 0.855f * u(rng));
    glm::vec3 r(g(rng), g(rng), g(rng));
    r = glm::normalize(r + glm::vec3(0, 0, 1e-3f));
    w.rx.push_back(r.x);
    w.ry.push_back(r.y);
    w.rz.push_back(r.z);
  }
  return w;
}

std::string costWorkloadName(Method method, int planes) {
  if (method == Method::Convex) return "convex_" + std::to_string(planes);
  return std::string(methodName(method));
}

const std::vector<std::string>& costTableWorkloads() {
  static const std::vector<std::string> names = {"infinite", "cheap_k",  "sphere",   "aabb",
                                                 "obb",      "convex_6", "convex_20"};
  return names;
}

void runScalarLookups(const LookupWorkload& w, LookupOutputs& out) {
  for (std::size_t i = 0; i < w.x.size(); ++i) {
    const seed::Lookup l =
        lookupScalar(w.proxy, {w.x[i], w.y[i], w.z[i]}, {w.rx[i], w.ry[i], w.rz[i]});
    out.dx[i] = l.direction.x;
    out.dy[i] = l.direction.y;
    out.dz[i] = l.direction.z;
    out.miss[i] = l.miss;
  }
}

void runBatchedLookups(const LookupWorkload& w, LookupOutputs& out) {
  lookupBatch(w.proxy, RaysSoA{w.x, w.y, w.z, w.rx, w.ry, w.rz},
              LookupsSoA{out.dx, out.dy, out.dz, out.miss});
}

}  // namespace probeproxy
