#include "plugin/jobs/mixing/mixing_inputs.h"

#include "core/errors/input_error.h"
#include "core/mixing/reflected_camera.h"
#include "core/proxy/proxy_shape.h"
#include "core/scene/scene_limits.h"
#include "geometry/level/load_level.h"
#include "geometry/probe_proxies/authored_proxy_shape.h"
#include "geometry/probe_proxies/build_probe_proxy.h"
#include "geometry/scene/json_values.h"

namespace probeproxy::jobs {

namespace {

std::string probeProblem(const std::string& probe, const std::string& what) {
  std::string problem = "probe '";
  problem += probe;
  problem += "' ";
  problem += what;
  return problem;
}

ConvexProxy convexVolume(const ProxyShape& shape, const std::filesystem::path& from,
                         const std::string& probe) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) return convexFromBox(*box);
  if (const auto* convex = std::get_if<ConvexProxy>(&shape)) {
    if (!convex->planes.empty() && !convex->triangles.empty()) return *convex;
  }
  std::string what = "has a ";
  what += methodId(shape);
  what += " proxy; the mixing step needs a box or convex proxy";
  throw InputError(from, probeProblem(probe, what));
}

}  // namespace

const Probe& findProbe(const Scene& scene, const std::string& name) {
  for (const Probe& p : scene.probes)
    if (p.name == name) return p;
  std::string known;
  for (const Probe& p : scene.probes) known += (known.empty() ? "" : ", ") + p.name;
  std::string problem = "no probe named '";
  problem += name;
  problem += "' (probes: ";
  problem += known;
  problem += ")";
  throw InputError(scene.file, problem);
}

std::filesystem::path probeCubemapPath(const Scene& scene, const Probe& probe) {
  if (!probe.cubemap) throw InputError(scene.file, probeProblem(probe.name, "has no cubemap"));
  std::filesystem::path cubemap(*probe.cubemap);
  return cubemap.is_relative() ? scene.file.parent_path() / cubemap : cubemap;
}

MixingProxies::MixingProxies(const Scene& scene, std::string proxiesJson)
    : scene_(scene), proxiesJson_(std::move(proxiesJson)) {}

MixingProxies::~MixingProxies() = default;

ConvexProxy MixingProxies::proxyFor(const Probe& probe) {
  if (!proxiesJson_.empty()) {
    if (!runtime_) runtime_ = std::make_unique<RuntimeExport>(readRuntimeExport(proxiesJson_));
    for (const RuntimeProbe& p : runtime_->probes) {
      if (p.name != probe.name) continue;
      if (p.box) return convexFromBox(*p.box);
      return convexVolume(p.convex, proxiesJson_, probe.name);
    }
    std::string problem = "no probe named '";
    problem += probe.name;
    problem += "'";
    throw InputError(proxiesJson_, problem);
  }
  if (const std::optional<ProxyShape> authored = authoredProxyShape(probe.proxy, scene_))
    return convexVolume(*authored, scene_.file, probe.name);
  if (!rayCaster_) {
    level_ = std::make_unique<LevelMesh>(loadLevel(scene_));
    rayCaster_ = std::make_unique<LevelRayCaster>(*level_);
  }
  const ProbeProxyBuild build = buildProbeProxy(*rayCaster_, probe, std::nullopt, {});
  return convexVolume(build.candidates.at(build.kept).shape, scene_.file, probe.name);
}

ReflectionPlane mixingPlane(const Scene& scene, const Probe& probe,
                            const std::optional<ReflectionPlane>& plane) {
  if (plane) {
    const glm::dvec3 p = plane->pointMeters, n = plane->normal;
    if (n == glm::dvec3(0.0))
      throw InputError("--plane", "the normal NX,NY,NZ is zero, expected a direction");
    if (!(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) <= kMaxSceneMeters)) {
      throw InputError("--plane", "the point PX,PY,PZ is past " +
                                      std::to_string(int(kMaxSceneMeters)) +
                                      " m from the origin (the limit of a scene)");
    }
    // As the scene reader normalises a plane's normal: one of 1e-320 or 1e308 is a direction.
    const std::array<double, 3> unit = normalized(std::array<double, 3>{n.x, n.y, n.z});
    return ReflectionPlane{p, {unit[0], unit[1], unit[2]}};
  }
  if (probe.reflectionPlanes.empty())
    throw InputError(scene.file,
                     probeProblem(probe.name, "has no reflection_planes; give one with --plane"));
  return probe.reflectionPlanes.front();
}

ProbeCorrection correctProbe(const Scene& scene, const Probe& probe, const Cubemap& source,
                             glm::dvec3 cameraMeters, const std::optional<ReflectionPlane>& plane,
                             MixingProxies& proxies, MixingMethod method) {
  ProbeCorrection c;
  c.plane = mixingPlane(scene, probe, plane);
  if (!(heightAbovePlaneMeters(cameraMeters, c.plane) > 0.0))
    throw InputError("--camera",
                     "the camera must be above the reflection plane (on the side "
                     "its normal points to)");
  c.proxy = proxies.proxyFor(probe);
  if (signedDistanceOutside(c.proxy.planes, probe.captureMeters) >= 0.0)
    throw InputError(scene.file, probeProblem(probe.name, "captures outside its proxy"));
  c.reflectedCameraMeters = reflectThroughPlane(cameraMeters, c.plane);
  c.corrected =
      correctCubemap(source, probe.captureMeters, c.proxy, c.reflectedCameraMeters, method);
  return c;
}

}  // namespace probeproxy::jobs
