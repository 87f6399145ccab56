#include "geometry/sweeps/break_sweeps.h"

#include "core/cube/cube_face.h"
#include "core/cube/cubemap.h"
#include "core/cube/cubemap_sampling.h"
#include "core/mixing/glossy_distortion.h"
#include "core/parallax/prepared_proxy.h"
#include "core/parallax/reference_lookup.h"
#include "geometry/evaluation/evaluate_shape.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

namespace probeproxy {

namespace {

const BoxShape kRoom{{0, 0, 1.5}, {5, 4, 1.5}};
constexpr int kRays = 1024;

struct Ray {
  glm::dvec3 xMeters, r;
};

glm::dvec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  glm::dvec3 v;
  do v = {g(rng), g(rng), g(rng)};
  while (glm::length(v) < 1e-6);
  return glm::normalize(v);
}

bool insideRoom(glm::dvec3 p, double marginMeters) {
  const glm::dvec3 d = glm::abs(p - kRoom.centerMeters);
  return glm::all(glm::lessThanEqual(d, kRoom.halfExtentsMeters - marginMeters));
}

// The float kernel's lookups of `rays` (rounded to float as a shader gets them) against the exact
// lookups `truth` (d* = H - C), as one sweep point.
SweepPoint measure(double parameter, const ProxyShape& shape, glm::dvec3 captureMeters,
                   const std::vector<Ray>& rays, const std::vector<glm::dvec3>& truth) {
  const PreparedProxy proxy = prepareProxy(shape, captureMeters);
  const std::size_t n = rays.size();
  std::vector<float> x(n), y(n), z(n), rx(n), ry(n), rz(n), dx(n), dy(n), dz(n);
  std::vector<std::uint8_t> miss(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = float(rays[i].xMeters.x), y[i] = float(rays[i].xMeters.y),
    z[i] = float(rays[i].xMeters.z);
    rx[i] = float(rays[i].r.x), ry[i] = float(rays[i].r.y), rz[i] = float(rays[i].r.z);
  }
  lookupBatch(proxy, {x, y, z, rx, ry, rz}, {dx, dy, dz, miss});
  SweepPoint point{parameter, {}, 0, std::nullopt, std::nullopt};
  std::vector<double> errors;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 d(dx[i], dy[i], dz[i]);
    const bool finite = std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z);
    if (!miss[i] && !finite) ++point.nonFinite;
    errors.push_back(miss[i] || !finite ? std::nan("") : angleBetweenDeg(d, truth[i]));
  }
  point.error = summarizeErrors(std::move(errors), 0);
  return point;
}

// Exact lookups in the room: it is the proxy, so H is where the ray leaves it.
std::vector<glm::dvec3> roomTruth(glm::dvec3 captureMeters, const std::vector<Ray>& rays) {
  std::vector<glm::dvec3> truth;
  for (const Ray& ray : rays)
    truth.push_back(referenceLookup(kRoom, captureMeters, ray.xMeters, ray.r).value());
  return truth;
}

// Shading points on the floor within `radius` of (cx, cy), upward unit directions.
std::vector<Ray> floorRays(glm::dvec2 centerMeters, double radiusMeters, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Ray> rays;
  while (rays.size() < kRays) {
    const glm::dvec2 p(u(rng), u(rng));
    if (glm::length(p) > 1.0) continue;
    const glm::dvec3 x(centerMeters + radiusMeters * p, 0.0);
    if (!insideRoom(x + glm::dvec3(0, 0, 1e-9), -1e-9)) continue;
    glm::dvec3 r = randomUnit(rng);
    r.z = std::abs(r.z) + 1e-3;
    rays.push_back({x, glm::normalize(r)});
  }
  return rays;
}

}  // namespace

Sweep distanceSweep() {
  Sweep sweep{"distance", "distance of the shading point from the capture point (m)", {}};
  const glm::dvec3 capture(0.5, 0.3, 1.5);
  const std::vector<std::pair<std::string, ProxyShape>> methods = {
      {"infinite", InfiniteShape{}},
      {"cheap_k", CheapKShape{0.25}},
      {"sphere", SphereShape{capture, glm::dvec3(4.0), {1, 0, 0, 0}}},
      {"aabb", kRoom},
      {"convex", convexFromBox(kRoom)}};
  for (const auto& [name, shape] : methods) sweep.series.push_back({name, {}});
  for (double s : {0.1, 0.25, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5}) {
    std::mt19937 rng(7);
    std::vector<Ray> rays;
    while (rays.size() < kRays) {
      const glm::dvec3 x = capture + s * randomUnit(rng);
      if (insideRoom(x, 0.01)) rays.push_back({x, randomUnit(rng)});
    }
    const std::vector<glm::dvec3> truth = roomTruth(capture, rays);
    for (std::size_t m = 0; m < methods.size(); ++m)
      sweep.series[m].points.push_back(measure(s, methods[m].second, capture, rays, truth));
  }
  return sweep;
}

Sweep roughnessSweep() {
  Sweep sweep{"roughness", "GGX roughness of the floor (alpha = roughness^2)", {}};
  GlossySetup setup;
  setup.proxy = convexFromBox(kRoom);
  setup.captureMeters = {0.5, 0.3, 1.5};
  setup.cameraMeters = {-2.0, 0.0, 1.7};
  setup.plane = {{0, 0, 0}, {0, 0, 1}};
  setup.pixels = kRays;
  const std::vector<double> roughnesses = {0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0};
  SweepSeries mixing{"mixing_plane", {}};
  for (const GlossyDistortion& g : glossyDistortion(setup, roughnesses))
    mixing.points.push_back({g.roughness, g.figures, 0, std::nullopt, std::nullopt});
  sweep.series.push_back(std::move(mixing));
  return sweep;
}

Sweep captureSweep() {
  Sweep sweep{"capture", "capture point x (m); the proxy's east wall is at x = 1 m", {}};
  // The room is the proxy (x in [-5, 1]): inside it every lookup is exact wherever the capture
  // point is; shading points around a capture point past the wall lie outside it and must be
  // flagged as misses, never returned as a direction.
  const BoxShape proxy{{-2, 0, 1.5}, {3, 4, 1.5}};
  sweep.series = {{"aabb", {}}, {"convex", {}}};
  for (double cx = -3.0; cx <= 3.01; cx += 0.5) {
    const glm::dvec3 capture(cx, 0.0, 1.5);
    const std::vector<Ray> rays = floorRays({cx, 0.0}, 1.5, 11);
    std::vector<glm::dvec3> truth;
    for (const Ray& ray : rays)
      truth.push_back(referenceLookup(proxy, capture, ray.xMeters, ray.r).value_or(ray.r));
    sweep.series[0].points.push_back(measure(cx, proxy, capture, rays, truth));
    sweep.series[1].points.push_back(measure(cx, convexFromBox(proxy), capture, rays, truth));
  }
  return sweep;
}

Sweep originSweep() {
  Sweep sweep{"origin", "distance of the level from the world origin (m)", {}};
  sweep.series = {{"aabb", {}}, {"convex", {}}, {"sphere", {}}, {"reference_double", {}}};
  const glm::dvec3 capture(0.5, 0.3, 1.5);
  const std::vector<Ray> local = floorRays({0.5, 0.3}, 3.0, 13);
  const std::vector<glm::dvec3> truth = roomTruth(capture, local);
  for (double distance : {1.0, 10.0, 100.0, 1e3, 1e4, 3e4, 1e5, 3e5, 1e6}) {
    const glm::dvec3 offset = distance * glm::normalize(glm::dvec3(1, 1, 1));
    std::vector<Ray> rays = local;
    for (Ray& ray : rays) ray.xMeters += offset;
    BoxShape room = kRoom;
    room.centerMeters += offset;
    const SphereShape sphere{capture + offset, glm::dvec3(4.0), {1, 0, 0, 0}};
    const std::vector<glm::dvec3> sphereTruth = [&] {
      std::vector<glm::dvec3> t;
      for (const Ray& ray : local)
        t.push_back(referenceLookup(SphereShape{capture, glm::dvec3(4.0), {1, 0, 0, 0}}, capture,
                                    ray.xMeters, ray.r)
                        .value());
      return t;
    }();
    sweep.series[0].points.push_back(measure(distance, room, capture + offset, rays, truth));
    sweep.series[1].points.push_back(
        measure(distance, convexFromBox(room), capture + offset, rays, truth));
    sweep.series[2].points.push_back(
        measure(distance, sphere, capture + offset, rays, sphereTruth));
    // The double reference on the moved level: exact up to double rounding.
    std::vector<double> errors;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const auto d = referenceLookup(room, capture + offset, rays[i].xMeters, rays[i].r);
      errors.push_back(d ? angleBetweenDeg(*d, truth[i]) : std::nan(""));
    }
    sweep.series[3].points.push_back(
        {distance, summarizeErrors(errors, 0), 0, std::nullopt, std::nullopt});
  }
  return sweep;
}

Sweep resolutionSweep() {
  Sweep sweep{"resolution", "cubemap face size (texels)", {}};
  sweep.series = {{"nearest_texel", {}}};
  // A smooth radiance with detail on a 10-degree scale, in [0, 1].
  const auto radiance = [](glm::dvec3 d) {
    return 0.5 + 0.5 * std::sin(6.0 * d.x) * std::cos(5.0 * d.y + 2.0 * d.z);
  };
  std::mt19937 rng(17);
  std::vector<glm::dvec3> directions;
  for (int i = 0; i < 4 * kRays; ++i) directions.push_back(randomUnit(rng));
  for (int n : {8, 16, 32, 64, 128, 256, 512}) {
    std::array<std::vector<float>, kCubeFaceCount> rgb;
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col) {
          const double v =
              radiance(glm::normalize(glm::dvec3(texelDirection(CubeFace(f), col, row, n))));
          for (int c = 0; c < 3; ++c) rgb[f].push_back(float(v));
        }
      }
    }
    const Cubemap cube = Cubemap::fromFaces(n, std::move(rgb));
    std::vector<double> errors;
    double absSum = 0.0;
    for (const glm::dvec3& d : directions) {
      // The texel a nearest fetch returns: its centre's direction against the exact one.
      const FaceUv fuv = faceUvFromDirection(glm::vec3(d));
      const int col = std::min(n - 1, int(fuv.uv.x * float(n)));
      const int row = std::min(n - 1, int(fuv.uv.y * float(n)));
      errors.push_back(angleBetweenDeg(glm::dvec3(texelDirection(fuv.face, col, row, n)), d));
      absSum += std::abs(double(sampleBilinear(cube, glm::vec3(d), 0.0f).x) - radiance(d));
    }
    SweepPoint point{double(n), summarizeErrors(errors, 0), 0, absSum / double(directions.size()),
                     std::nullopt};
    sweep.series[0].points.push_back(point);
  }
  return sweep;
}

std::vector<Sweep> allSweeps() {
  return {distanceSweep(), roughnessSweep(), captureSweep(),
          originSweep(),   concavitySweep(), resolutionSweep()};
}

std::optional<double> firstP95Above(const SweepSeries& series, double limitDeg) {
  for (const SweepPoint& p : series.points) {
    if (!(p.error.p95Deg <= limitDeg)) return p.parameter;  // NaN (all missed) counts as above
  }
  return std::nullopt;
}

std::string sweepsJson(const std::vector<Sweep>& sweeps) {
  const auto number = [](double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Sweep& s : sweeps) {
    nlohmann::ordered_json series = nlohmann::ordered_json::array();
    for (const SweepSeries& m : s.series) {
      nlohmann::ordered_json points = nlohmann::ordered_json::array();
      for (const SweepPoint& p : m.points) {
        points.push_back({{"parameter", p.parameter},
                          {"median_deg", number(p.error.medianDeg)},
                          {"p95_deg", number(p.error.p95Deg)},
                          {"miss_rate", number(p.error.missRate)},
                          {"non_finite", p.nonFinite},
                          {"image_mae", number(p.imageMeanAbsError.value_or(std::nan("")))},
                          {"planes", p.planes ? nlohmann::ordered_json(*p.planes)
                                              : nlohmann::ordered_json(nullptr)}});
      }
      series.push_back({{"method", m.method}, {"points", std::move(points)}});
    }
    out.push_back({{"name", s.name}, {"parameter", s.parameter}, {"series", std::move(series)}});
  }
  return nlohmann::ordered_json{{"sweeps", std::move(out)}}.dump(2) + "\n";
}

}  // namespace probeproxy
