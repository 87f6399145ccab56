#pragma once
// What the mixing step (core/mixing/) needs from a scene, shared by the `correct` job (one
// probe) and the `blend` job with a camera (every probe it mixes): the probe, its cubemap,
// its proxy as a convex volume and the reflection plane. Each failure is an InputError naming
// the file or option at fault.

#include "core/cube/cubemap.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/proxy/convex_proxy.h"
#include "core/scene/scene.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/level_mesh.h"
#include "geometry/raycast/level_ray_caster.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace probeproxy::jobs {

const Probe& findProbe(const Scene& scene, const std::string& name);

// The probe's `cubemap` resolved against the scene's folder (six files or one image).
std::filesystem::path probeCubemapPath(const Scene& scene, const Probe& probe);

// Where the mixing step's proxies come from: the kept ones of a `build` export when
// proxiesJson is given, else the ones the scene file authors, else (`auto`) ones built now from
// the level. The export and the level are read once, on first need, however many probes ask.
// The mixing step draws planes and triangles, so a sphere, cheap_k or infinite proxy is refused.
class MixingProxies {
 public:
  MixingProxies(const Scene& scene, std::string proxiesJson);
  ~MixingProxies();
  ConvexProxy proxyFor(const Probe& probe);

 private:
  const Scene& scene_;
  std::string proxiesJson_;
  std::unique_ptr<RuntimeExport> runtime_;
  std::unique_ptr<LevelMesh> level_;
  std::unique_ptr<LevelRayCaster> rayCaster_;
};

// `plane` when given (its normal must not be zero), else the probe's first reflection_planes
// entry.
ReflectionPlane mixingPlane(const Scene& scene, const Probe& probe,
                            const std::optional<ReflectionPlane>& plane);

struct ProbeCorrection {
  ReflectionPlane plane;
  ConvexProxy proxy;
  glm::dvec3 reflectedCameraMeters{0.0};  // the camera mirrored through the plane
  CorrectedCubemap corrected;             // centred at the reflected camera, every mip level
};

// The probe's cubemap corrected by the mixing step for a camera over the plane (mixingPlane,
// MixingProxies). Refuses a camera that is not above the plane and a capture point outside the
// proxy.
ProbeCorrection correctProbe(const Scene& scene, const Probe& probe, const Cubemap& source,
                             glm::dvec3 cameraMeters, const std::optional<ReflectionPlane>& plane,
                             MixingProxies& proxies, MixingMethod method);

}  // namespace probeproxy::jobs
