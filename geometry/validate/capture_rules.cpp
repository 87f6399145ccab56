// The rules about one probe's own pieces: its authored mesh, and where its capture point is.

#include "geometry/probe_proxies/authored_proxy_shape.h"
#include "geometry/raycast/capture_depth_cube.h"
#include "geometry/validate/proxy_mesh_checks.h"
#include "geometry/validate/validation_rules.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace probeproxy {

std::string formatPoint(glm::dvec3 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", p.x, p.y, p.z);
  return text;
}

double metersOutside(const ProxyShape& shape, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxShape>(&shape))
    return signedDistanceOutside(convexFromBox(*box).planes, p);
  if (const auto* convex = std::get_if<ConvexProxy>(&shape))
    return signedDistanceOutside(convex->planes, p);
  if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
    // Exact for a sphere; for an ellipsoid the scaled distance along the shortest radius,
    // which has the right sign and is exact on the boundary.
    const glm::dvec3 local = glm::conjugate(sphere->worldFromSphere) * (p - sphere->centerMeters);
    const double minRadius =
        std::min({sphere->radiiMeters.x, sphere->radiiMeters.y, sphere->radiiMeters.z});
    return (glm::length(local / sphere->radiiMeters) - 1.0) * minRadius;
  }
  return -std::numeric_limits<double>::infinity();
}

void checkAuthoredMesh(const Scene& scene, const Probe& probe,
                       std::vector<ValidationFinding>& out) {
  const auto* authored = std::get_if<AuthoredConvexMesh>(&probe.proxy);
  if (authored == nullptr) return;
  const LevelMesh mesh = loadAuthoredProxyMesh(*authored, scene);
  for (ProxyMeshFinding& f : checkProxyMesh(mesh, probe.captureMeters)) {
    if (f.rule == "proxy_misses_capture") continue;  // capture_outside_proxy says it
    out.push_back({probe.name, std::move(f.rule), std::move(f.severity), f.value, f.limit,
                   "probe '" + probe.name + "': proxy mesh " + authored->meshAsWritten.string() +
                       ": " + f.message,
                   std::move(f.hint)});
  }
}

namespace {

// "probe 'p' captures at (x, y, z), d m outside its <what>": the two capture rules' finding.
ValidationFinding captureFinding(const Probe& probe, const char* rule, double outside,
                                 const char* what, const char* hint) {
  char value[32];
  std::snprintf(value, sizeof value, "%.3f", outside);
  return {probe.name,
          rule,
          "error",
          outside,
          0.0,
          "probe '" + probe.name + "' captures at " + formatPoint(probe.captureMeters) + ", " +
              value + " m outside its " + what,
          hint};
}

// How far outside the outer range, metres (negative inside; for a box the largest excess over
// the half-extents along its own axes).
double metersOutsideInfluence(const InfluenceVolume& influence, glm::dvec3 p) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const glm::dvec3 local = glm::conjugate(box->worldFromBox) * (p - box->centerMeters);
    const glm::dvec3 excess = glm::abs(local) - box->halfExtentsMeters;
    return std::max({excess.x, excess.y, excess.z});
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  return glm::distance(p, sphere.centerMeters) - sphere.radiusMeters;
}

}  // namespace

void checkCaptureInsideProxy(const Probe& probe, const ProxyShape& authored,
                             std::vector<ValidationFinding>& out) {
  const double outside = metersOutside(authored, probe.captureMeters);
  if (outside < 0.0) return;
  out.push_back(captureFinding(probe, "capture_outside_proxy", outside, "authored proxy",
                               "move the capture point into the proxy, or enlarge the proxy "
                               "around it (parallax correction needs the capture point "
                               "strictly inside)"));
}

void checkCaptureInsideInfluence(const Probe& probe, std::vector<ValidationFinding>& out) {
  if (insideInfluence(probe.influence, probe.captureMeters)) return;
  const double outside = metersOutsideInfluence(probe.influence, probe.captureMeters);
  out.push_back(captureFinding(probe, "capture_outside_influence", outside, "influence volume",
                               "move the capture point into the influence volume, or the "
                               "volume over it (build and export refuse this probe until "
                               "then)"));
}

void checkCaptureInsideLevel(const LevelRayCaster& level, const Probe& probe,
                             std::vector<ValidationFinding>& out) {
  // A capture point inside the level sees the front of the level's surfaces (wound towards the
  // side a player sees) nearly everywhere; outside the level, or inside a wall, it sees the
  // void or the backs of surfaces. More than half of the directions so: the build's own
  // threshold for "sees no level" (build_probe_proxy.cpp), unless most of what lies right under
  // it is the front of a floor (below).
  constexpr int kFaceSize = 32;  // 6 x 32 x 32 rays: shares to 0.02%
  constexpr double kLimit = 0.5;
  // Right under: within 30 degrees of straight down, 0.9 m across from 1.6 m up, so a
  // walkway's width (half the lower half was too wide: the void beside a 2 m walkway filled it).
  constexpr double kCosFloorCone = 0.8660254037844386;
  const std::vector<Ray> rays = depthCubeRays(probe.captureMeters, kFaceSize);
  const std::vector<RayHit> hits = castDepthCubeRays(level, probe.captureMeters, kFaceSize);
  std::size_t unseen = 0, backs = 0, downward = 0, floorBelow = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const bool back = hits[i].hit() && glm::dot(glm::dvec3(hits[i].geometricNormal),
                                                glm::dvec3(rays[i].direction)) > 0.0;
    if (!hits[i].hit() || back) ++unseen;
    if (back) ++backs;
    if (glm::normalize(glm::dvec3(rays[i].direction)).z < -kCosFloorCone) {
      ++downward;
      if (hits[i].hit() && !back) ++floorBelow;
    }
  }
  const double share = static_cast<double>(unseen) / static_cast<double>(hits.size());
  // Over a platform open to the sky, the whole upper half and the void past the platform's
  // edges see no level (evilspace's platforms and walkways in space: 55-73% of a capture
  // point's directions), yet the point is where a player stands. What tells it from a point
  // outside the level or inside a wall is what lies right under it: the front of the floor it
  // stands over, and outside, the void or the backs of the level's faces.
  if (share <= kLimit || 2 * floorBelow > downward) return;
  ValidationFinding f;
  f.probe = probe.name;
  f.rule = "capture_outside_level";
  f.severity = "warning";
  f.value = share;
  f.limit = kLimit;
  char text[64];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
  f.message = "probe '" + probe.name + "' captures at " + formatPoint(probe.captureMeters) + ": " +
              text +
              " of its directions see no level or the back of a surface; it is "
              "outside the level or inside a wall" +
              (2 * backs > hits.size()
                   ? std::string(", or the level's faces point away from its rooms (inverted "
                                 "normals)")
                   : std::string());
  f.hint = 2 * backs > hits.size() ? "move the capture point into the room it serves; if every "
                                     "probe shows this, flip the level's normals where it is made"
                                   : "move the capture point into the room it serves";
  out.push_back(std::move(f));
}

}  // namespace probeproxy
