// The float lookup methods (seed ports and batched kernels, core/parallax/prepared_proxy.h)
// against the double-precision reference, on degenerate inputs, far from the origin, and in a
// box room whose exact answer is known.

#include "core/parallax/prepared_proxy.h"
#include "core/parallax/reference_lookup.h"
#include "core/parallax/seed_lookups.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace probeproxy {
namespace {

double angleDegrees(glm::dvec3 a, glm::dvec3 b) {
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

// The capture point as prepareProxy keeps it. volatile: GCC 12.2 -O2 drops the round trip
// through float for x and y otherwise (see prepared_proxy.cpp).
glm::dvec3 roundedToFloat(glm::dvec3 p) {
  volatile float x = static_cast<float>(p.x), y = static_cast<float>(p.y),
                 z = static_cast<float>(p.z);
  return {x, y, z};
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

glm::dquat rotation(double degrees, glm::dvec3 axis) {
  return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

// How far p lies outside the shape, in metres (negative inside); 0 for shapes without volume.
double outsideBy(const ProxyShape& shape, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxShape>(&shape))
    return signedDistanceOutside(convexFromBox(*box).planes, p);
  if (const auto* convex = std::get_if<ConvexProxy>(&shape))
    return signedDistanceOutside(convex->planes, p);
  if (const auto* s = std::get_if<SphereShape>(&shape)) {
    const glm::dvec3 local = glm::conjugate(s->worldFromSphere) * (p - s->centerMeters);
    const double minRadius =
        std::min(s->radiiMeters.x, std::min(s->radiiMeters.y, s->radiiMeters.z));
    return (glm::length(local / s->radiiMeters) - 1.0) * minRadius;  // a lower bound for outside
  }
  return -1.0;
}

struct Case {
  std::string name;
  ProxyShape shape;
  glm::dvec3 center{0.0};  // where to sample points around
  double reach = 6.0;      // sampling half-size, metres
};

std::vector<Case> cases(glm::dvec3 offset = glm::dvec3(0.0)) {
  std::vector<Case> out;
  out.push_back({"infinite", InfiniteShape{}, offset});
  out.push_back({"cheap_k", CheapKShape{0.3}, offset});
  out.push_back(
      {"sphere",
       SphereShape{offset + glm::dvec3(0.5, -0.3, 1.0), {4.0, 3.0, 2.5}, rotation(25, {1, 2, 3})},
       offset + glm::dvec3(0.5, -0.3, 1.0)});
  out.push_back({"aabb", BoxShape{offset + glm::dvec3(1.0, 2.0, 1.5), {5.0, 4.0, 1.5}},
                 offset + glm::dvec3(1.0, 2.0, 1.5)});
  out.push_back(
      {"obb",
       BoxShape{offset + glm::dvec3(-1.0, 0.5, 2.0), {4.0, 3.0, 2.0}, rotation(37, {0.2, -0.4, 1})},
       offset + glm::dvec3(-1.0, 0.5, 2.0)});
  ConvexProxy convex =
      convexFromBox(BoxShape{offset + glm::dvec3(0, 0, 1.5), {5, 4, 1.5}, rotation(20, {0, 0, 1})});
  const glm::dvec3 slope = glm::normalize(glm::dvec3(1, 0.5, 1.2));  // a slanted ceiling
  convex.planes.push_back({slope, glm::dot(slope, offset + glm::dvec3(2, 1, 2.2))});
  out.push_back({"convex", convex, offset + glm::dvec3(0, 0, 1.5)});
  ConvexProxy open = convexFromBox(BoxShape{offset + glm::dvec3(0, 0, 1.5), {5, 4, 1.5}});
  open.planes.erase(open.planes.begin() + 4);  // no ceiling: rays going up never leave
  out.push_back({"convex_unbounded", open, offset + glm::dvec3(0, 0, 1.5)});
  return out;
}

glm::dvec3 samplePoint(std::mt19937& rng, const Case& c, double minOutside, double maxOutside) {
  std::uniform_real_distribution<double> u(-c.reach, c.reach);
  for (;;) {
    const glm::dvec3 p = c.center + glm::dvec3(u(rng), u(rng), u(rng));
    const double d = outsideBy(c.shape, p);
    if (d >= minOutside && d <= maxOutside) return p;
  }
}

glm::dvec3 randomDirection(std::mt19937& rng) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> length(0.3, 3.0);
  for (;;) {
    const glm::dvec3 v(g(rng), g(rng), g(rng));
    if (glm::length(v) > 1e-3) return glm::normalize(v) * length(rng);
  }
}

struct Rays {
  std::vector<float> x, y, z, rx, ry, rz;
  void push(glm::vec3 p, glm::vec3 r) {
    x.push_back(p.x), y.push_back(p.y), z.push_back(p.z);
    rx.push_back(r.x), ry.push_back(r.y), rz.push_back(r.z);
  }
  glm::vec3 point(std::size_t i) const { return {x[i], y[i], z[i]}; }
  glm::vec3 dir(std::size_t i) const { return {rx[i], ry[i], rz[i]}; }
  RaysSoA view() const { return {x, y, z, rx, ry, rz}; }
};

struct Results {
  explicit Results(std::size_t n) : x(n), y(n), z(n), miss(n) {}
  std::vector<float> x, y, z;
  std::vector<std::uint8_t> miss;
  LookupsSoA view() { return {x, y, z, miss}; }
  glm::vec3 dir(std::size_t i) const { return {x[i], y[i], z[i]}; }
};

// Compares scalar and batched lookups of every ray with the reference (computed from the same
// float inputs and the float capture point). Returns the largest angle seen, in degrees.
double checkAgainstReference(const Case& c, glm::dvec3 capture, const Rays& rays,
                             double maxDegrees) {
  const PreparedProxy proxy = prepareProxy(c.shape, capture);
  const glm::dvec3 captureF = roundedToFloat(capture);
  Results batched(rays.x.size());
  lookupBatch(proxy, rays.view(), batched.view());
  double worst = 0.0;
  int failures = 0;
  for (std::size_t i = 0; i < rays.x.size() && failures < 5; ++i) {
    const std::optional<glm::dvec3> ref =
        referenceLookup(c.shape, captureF, glm::dvec3(rays.point(i)), glm::dvec3(rays.dir(i)));
    const seed::Lookup scalar = lookupScalar(proxy, rays.point(i), rays.dir(i));
    const std::string where = c.name + " ray " + std::to_string(i);
    EXPECT_TRUE(finite(scalar.direction)) << where;
    EXPECT_TRUE(finite(batched.dir(i))) << where;
    EXPECT_EQ(scalar.miss, !ref.has_value()) << where;
    EXPECT_EQ(batched.miss[i] != 0, !ref.has_value()) << where;
    if (scalar.miss != !ref.has_value() || (batched.miss[i] != 0) != !ref.has_value()) ++failures;
    if (!ref) {
      EXPECT_EQ(scalar.direction, glm::vec3(0.0f)) << where;
      EXPECT_EQ(batched.dir(i), glm::vec3(0.0f)) << where;
      continue;
    }
    if (scalar.miss || batched.miss[i]) continue;
    const double aScalar = angleDegrees(glm::dvec3(scalar.direction), *ref);
    const double aBatched = angleDegrees(glm::dvec3(batched.dir(i)), *ref);
    EXPECT_LT(aScalar, maxDegrees)
        << where << " x " << rays.x[i] << "," << rays.y[i] << "," << rays.z[i] << " r "
        << rays.rx[i] << "," << rays.ry[i] << "," << rays.rz[i] << " d " << scalar.direction.x
        << "," << scalar.direction.y << "," << scalar.direction.z << " ref " << ref->x << ","
        << ref->y << "," << ref->z;
    EXPECT_LT(aBatched, maxDegrees) << where;
    if (aScalar >= maxDegrees || aBatched >= maxDegrees) ++failures;
    worst = std::max(worst, std::max(aScalar, aBatched));
  }
  return worst;
}

class ParallaxMethodsAgreement : public ::testing::TestWithParam<int> {};

TEST_P(ParallaxMethodsAgreement, ScalarAndBatchedMatchTheReferenceOn100kRays) {
  const Case c = cases()[static_cast<std::size_t>(GetParam())];
  std::mt19937 rng(1000 + GetParam());
  const glm::dvec3 capture = samplePoint(rng, c, -1e9, -0.5);
  Rays rays;
  for (int i = 0; i < 100000; ++i) {
    // One point in ten well outside the proxy: a miss for every method with a volume.
    const bool outside = i % 10 == 9 && c.name != "infinite" && c.name != "cheap_k";
    const glm::dvec3 x =
        outside ? samplePoint(rng, c, 0.05, 1e9) : samplePoint(rng, c, -1e9, -0.01);
    rays.push(glm::vec3(x), glm::vec3(randomDirection(rng)));
  }
  const double worst = checkAgainstReference(c, capture, rays, 1e-3);
  RecordProperty("worst_degrees", std::to_string(worst));
}

INSTANTIATE_TEST_SUITE_P(EveryMethod, ParallaxMethodsAgreement, ::testing::Range(0, 7),
                         [](const ::testing::TestParamInfo<int>& param) {
                           return cases()[static_cast<std::size_t>(param.param)].name;
                         });

TEST(ParallaxMethodsSeedPorts, WorldFrameAabbMatchesTheReference) {
  // The seed port itself, in world coordinates (not through PreparedProxy's capture frame).
  const BoxShape box{{1.0, 2.0, 1.5}, {5.0, 4.0, 1.5}};
  const Case c{"aabb", box, box.centerMeters};
  std::mt19937 rng(7);
  const glm::vec3 capture(samplePoint(rng, c, -1e9, -0.5));
  for (int i = 0; i < 10000; ++i) {
    const glm::vec3 x(samplePoint(rng, c, -1e9, -0.01));
    const glm::vec3 r(randomDirection(rng));
    const seed::Lookup got =
        seed::aabb(glm::vec3(box.centerMeters - box.halfExtentsMeters),
                   glm::vec3(box.centerMeters + box.halfExtentsMeters), capture, x, r);
    const auto ref = referenceLookup(box, glm::dvec3(capture), glm::dvec3(x), glm::dvec3(r));
    ASSERT_TRUE(ref && !got.miss);
    ASSERT_LT(angleDegrees(glm::dvec3(got.direction), *ref), 1e-3);
  }
}

// Degenerate rays for a case: exactly parallel to axes and faces, points exactly on the
// boundary and outside it, zero vectors, denormal and huge directions.
Rays degenerateRays(const Case& c, glm::dvec3 capture) {
  Rays rays;
  std::vector<glm::vec3> dirs;
  for (int axis = 0; axis < 3; ++axis)
    for (float s : {1.0f, -1.0f}) {
      glm::vec3 d(0.0f);
      d[axis] = s;
      dirs.push_back(d);
      glm::vec3 diag(s);
      diag[axis] = 0.0f;  // parallel to the two faces normal to `axis`
      dirs.push_back(diag);
    }
  dirs.push_back(glm::vec3(0.0f));
  dirs.push_back(glm::vec3(-0.0f, 0.0f, -0.0f));
  dirs.push_back(glm::vec3(1e-40f, 0.0f, 0.0f));   // denormal
  dirs.push_back(glm::vec3(1e18f, -1e18f, 1.0f));  // huge, |r|^2 still finite
  // Face-parallel directions of oriented boxes and convex planes, as float.
  if (const auto* box = std::get_if<BoxShape>(&c.shape)) {
    const glm::dmat3 axes = glm::mat3_cast(box->worldFromBox);
    for (int a = 0; a < 3; ++a) {
      dirs.push_back(glm::vec3(axes[a]));
      dirs.push_back(glm::vec3(axes[a] + axes[(a + 1) % 3]));
    }
  }
  std::vector<glm::vec3> points = {glm::vec3(capture), glm::vec3(c.center)};
  // Points exactly on the boundary: on each face of the box (the float point nearest to it)
  // and at the corners, plus points 0.5 m outside.
  if (const auto* box = std::get_if<BoxShape>(&c.shape)) {
    const glm::dmat3 axes = glm::mat3_cast(box->worldFromBox);
    for (int a = 0; a < 3; ++a)
      for (double s : {1.0, -1.0}) {
        points.push_back(glm::vec3(box->centerMeters + s * axes[a] * box->halfExtentsMeters[a]));
        points.push_back(
            glm::vec3(box->centerMeters + s * axes[a] * (box->halfExtentsMeters[a] + 0.5)));
      }
    points.push_back(glm::vec3(box->centerMeters + axes * box->halfExtentsMeters));
    points.push_back(glm::vec3(box->centerMeters - axes * box->halfExtentsMeters));
  }
  if (const auto* s = std::get_if<SphereShape>(&c.shape)) {
    for (int a = 0; a < 3; ++a) {
      glm::dvec3 local(0.0);
      local[a] = s->radiiMeters[a];
      points.push_back(glm::vec3(s->centerMeters + s->worldFromSphere * local));
      points.push_back(glm::vec3(s->centerMeters + s->worldFromSphere * (local * 1.2)));
    }
  }
  if (const auto* convex = std::get_if<ConvexProxy>(&c.shape)) {
    for (const ProxyPlane& p : convex->planes) {
      // The projection of the centre on each plane (on the boundary if it is a face there).
      const glm::dvec3 on = c.center - (glm::dot(p.normal, c.center) - p.offsetMeters) * p.normal;
      points.push_back(glm::vec3(on));
      points.push_back(glm::vec3(on + 0.5 * p.normal));
    }
  }
  for (glm::vec3 p : points)
    for (glm::vec3 d : dirs) rays.push(p, d);
  return rays;
}

void expectStable(const Case& c, glm::dvec3 capture, const Rays& rays, bool compareFlags) {
  const PreparedProxy proxy = prepareProxy(c.shape, capture);
  Results batched(rays.x.size());
  lookupBatch(proxy, rays.view(), batched.view());
  const glm::dvec3 captureF = roundedToFloat(capture);
  for (std::size_t i = 0; i < rays.x.size(); ++i) {
    const seed::Lookup scalar = lookupScalar(proxy, rays.point(i), rays.dir(i));
    const std::string where = c.name + " ray " + std::to_string(i);
    ASSERT_TRUE(finite(scalar.direction)) << where;
    ASSERT_TRUE(finite(batched.dir(i))) << where;
    ASSERT_EQ(scalar.miss, batched.miss[i] != 0) << where;
    if (scalar.miss) {
      ASSERT_EQ(scalar.direction, glm::vec3(0.0f)) << where;
      ASSERT_EQ(batched.dir(i), glm::vec3(0.0f)) << where;
    } else {
      ASSERT_NE(scalar.direction, glm::vec3(0.0f)) << where;
    }
    const glm::vec3 r = rays.dir(i);
    if (r == glm::vec3(0.0f)) {
      ASSERT_TRUE(scalar.miss) << where;
    }
    if (outsideBy(c.shape, glm::dvec3(rays.point(i))) > 0.1) {
      ASSERT_TRUE(scalar.miss) << where;
    }
    if (compareFlags && std::abs(r.x) < 1e17f && std::abs(r.x) != 1e-40f) {
      const auto ref = referenceLookup(c.shape, captureF, glm::dvec3(rays.point(i)), glm::dvec3(r));
      ASSERT_EQ(scalar.miss, !ref.has_value()) << where;
    }
  }
}

TEST(ParallaxMethodsStability, ParallelRaysBoundaryPointsAndZeroVectors) {
  for (const Case& c : cases()) {
    std::mt19937 rng(11);
    expectStable(c, samplePoint(rng, c, -1e9, -0.5), degenerateRays(c, c.center), true);
  }
}

TEST(ParallaxMethodsStability, CapturePointOnTheBoundary) {
  for (const Case& c : cases()) {
    if (c.name == "infinite" || c.name == "cheap_k") continue;
    const Rays probe = degenerateRays(c, c.center);
    // Every boundary point of degenerateRays is tried as the capture point, with the rays
    // from it (a lookup landing on C is a flagged miss) and random rays from inside.
    for (std::size_t i = 0; i < probe.x.size(); i += 20) {
      const glm::dvec3 capture(probe.point(i));
      if (std::abs(outsideBy(c.shape, capture)) > 1e-4) continue;
      Rays rays = degenerateRays(c, capture);
      std::mt19937 rng(static_cast<unsigned>(i));
      for (int k = 0; k < 200; ++k)
        rays.push(glm::vec3(samplePoint(rng, c, -1e9, -0.01)), glm::vec3(randomDirection(rng)));
      expectStable(c, capture, rays, false);
    }
  }
}

TEST(ParallaxMethodsStability, TenMetreBoxes100kmFromTheOrigin) {
  const glm::dvec3 far(1e5, -1e5, 1e5);
  for (const Case& c : cases(far)) {
    std::mt19937 rng(13);
    const glm::dvec3 capture = samplePoint(rng, c, -1e9, -0.5);
    Rays rays = degenerateRays(c, capture);
    expectStable(c, capture, rays, false);
    // Well inside (float spacing here is 8 mm): hits close to the reference; well outside:
    // misses.
    Rays inside, outside;
    for (int k = 0; k < 5000; ++k) {
      inside.push(glm::vec3(samplePoint(rng, c, -1e9, -0.05)), glm::vec3(randomDirection(rng)));
      if (c.name != "infinite" && c.name != "cheap_k")
        outside.push(glm::vec3(samplePoint(rng, c, 0.5, 1e9)), glm::vec3(randomDirection(rng)));
    }
    checkAgainstReference(c, capture, inside, 0.05);
    expectStable(c, capture, outside, false);
  }
}

// A box room: the walls are the box, so the true hit H of a ray from inside is analytic and an
// exact proxy must reproduce d* = H - C.
TEST(ParallaxMethodsBoxRoom, ExactBoxGivesTheTrueHit) {
  const glm::dvec3 half(4.0, 3.0, 1.5), center(2.0, -1.0, 1.5);
  for (double yawDegrees : {0.0, 30.0}) {
    const glm::dquat worldFromRoom = rotation(yawDegrees, {0, 0, 1});
    const BoxShape room{center, half, worldFromRoom};
    const std::vector<ProxyShape> proxies = {room, convexFromBox(room)};
    const glm::dvec3 capture = center + worldFromRoom * glm::dvec3(-1.0, 0.7, -0.3);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Rays rays;
    std::vector<glm::dvec3> trueHits;
    for (int i = 0; i < 20000; ++i) {
      const glm::dvec3 local = glm::dvec3(u(rng), u(rng), u(rng)) * (half - 0.01);
      const glm::vec3 x(center + worldFromRoom * local);
      const glm::vec3 r(randomDirection(rng));
      // The walls, floor and ceiling in the room's frame: the nearest one ahead.
      const glm::dvec3 p = glm::conjugate(worldFromRoom) * (glm::dvec3(x) - center);
      const glm::dvec3 d = glm::conjugate(worldFromRoom) * glm::dvec3(r);
      double t = 1e300;
      for (int a = 0; a < 3; ++a)
        if (d[a] != 0) t = std::min(t, ((d[a] > 0 ? half[a] : -half[a]) - p[a]) / d[a]);
      rays.push(x, r);
      trueHits.push_back(glm::dvec3(x) + t * glm::dvec3(r));
    }
    for (const ProxyShape& shape : proxies) {
      const PreparedProxy proxy = prepareProxy(shape, capture);
      Results batched(rays.x.size());
      lookupBatch(proxy, rays.view(), batched.view());
      double worst = 0.0;
      for (std::size_t i = 0; i < rays.x.size(); ++i) {
        const seed::Lookup scalar = lookupScalar(proxy, rays.point(i), rays.dir(i));
        ASSERT_FALSE(scalar.miss);
        ASSERT_EQ(batched.miss[i], 0);
        const glm::dvec3 ideal = trueHits[i] - capture;
        worst = std::max({worst, angleDegrees(glm::dvec3(scalar.direction), ideal),
                          angleDegrees(glm::dvec3(batched.dir(i)), ideal)});
      }
      EXPECT_LT(worst, 0.05) << methodName(proxy.method) << " yaw " << yawDegrees;
    }
  }
}

TEST(ParallaxMethodsInterface, MethodsAndInputChecks) {
  EXPECT_EQ(prepareProxy(InfiniteShape{}, {}).method, Method::Infinite);
  EXPECT_EQ(prepareProxy(CheapKShape{0.1}, {}).method, Method::CheapK);
  EXPECT_EQ(prepareProxy(SphereShape{}, {}).method, Method::Sphere);
  EXPECT_EQ(prepareProxy(BoxShape{}, {}).method, Method::Aabb);
  EXPECT_EQ(prepareProxy(BoxShape{{}, {1, 1, 1}, rotation(10, {0, 0, 1})}, {}).method, Method::Obb);
  EXPECT_EQ(prepareProxy(convexFromBox(BoxShape{}), {}).method, Method::Convex);
  for (const Case& c : cases()) {
    if (c.name != "convex_unbounded") {
      EXPECT_EQ(methodName(prepareProxy(c.shape, c.center).method), methodId(c.shape));
    }
  }
  EXPECT_THROW(prepareProxy(BoxShape{{}, {1, 0, 1}}, {}), std::invalid_argument);
  EXPECT_THROW(prepareProxy(SphereShape{{}, {1, -1, 1}}, {}), std::invalid_argument);
  EXPECT_THROW(prepareProxy(InfiniteShape{}, {NAN, 0, 0}), std::invalid_argument);
  ConvexProxy bad;
  bad.planes.push_back({{0, 0, 2}, 1.0});
  EXPECT_THROW(prepareProxy(bad, {}), std::invalid_argument);

  Rays rays;
  rays.push({0, 0, 0}, {1, 0, 0});
  Results wrong(2);
  EXPECT_THROW(lookupBatch(prepareProxy(BoxShape{}, {}), rays.view(), wrong.view()),
               std::invalid_argument);
  Results empty(0);
  EXPECT_NO_THROW(lookupBatch(prepareProxy(BoxShape{}, {}), Rays{}.view(), empty.view()));
}

}  // namespace
}  // namespace probeproxy
