// `probeproxy correct`: the mixing step of seed 000 for one probe, camera and reflection plane,
// written as a cubemap (six EXRs) centred at the reflected camera.

#include "core/cube/cubemap_io.h"
#include "core/errors/input_error.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/mixing/reflected_camera.h"
#include "core/proxy/proxy_shape.h"
#include "geometry/build/authored_proxy_shape.h"
#include "geometry/build/build_probe_proxy.h"
#include "geometry/export/runtime_export.h"
#include "geometry/level/load_level.h"
#include "geometry/scene/scene_file.h"
#include "plugin/cli/number_list.h"
#include "plugin/cli/verb.h"

#include <iostream>
#include <memory>
#include <string>

namespace probeproxy::cli {

namespace {

struct CorrectOptions {
  std::string scene, probe, camera, plane, out, method = "mixing_plane", proxies;
};

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

// The mixing step draws planes and triangles: boxes and convex proxies. A sphere, cheap_k or
// infinite proxy has no such volume.
ConvexProxy convexVolume(const ProxyShape& shape, const std::filesystem::path& from,
                         const std::string& probe) {
  if (const auto* box = std::get_if<BoxShape>(&shape)) return convexFromBox(*box);
  if (const auto* convex = std::get_if<ConvexProxy>(&shape)) {
    if (!convex->planes.empty() && !convex->triangles.empty()) return *convex;
  }
  std::string problem = "probe '";
  problem += probe;
  problem += "' has a ";
  problem += methodId(shape);
  problem += " proxy; the mixing step needs a box or convex proxy";
  throw InputError(from, problem);
}

// The proxy a probe is corrected with: the kept one of a `build` export when given, else the
// one the scene file authors, else (`auto`) one built now from the level.
ConvexProxy probeProxy(const Scene& scene, const Probe& probe, const std::string& proxiesJson) {
  if (!proxiesJson.empty()) {
    const RuntimeExport runtime = readRuntimeExport(proxiesJson);
    for (const RuntimeProbe& p : runtime.probes) {
      if (p.name != probe.name) continue;
      if (p.box) return convexFromBox(*p.box);
      return convexVolume(p.convex, proxiesJson, probe.name);
    }
    std::string problem = "no probe named '";
    problem += probe.name;
    problem += "'";
    throw InputError(proxiesJson, problem);
  }
  if (const std::optional<ProxyShape> authored = authoredProxyShape(probe.proxy, scene))
    return convexVolume(*authored, scene.file, probe.name);
  const LevelMesh level = loadLevel(scene);
  const LevelRayCaster rayCaster(level);
  const ProbeProxyBuild build = buildProbeProxy(rayCaster, probe, std::nullopt, {});
  return convexVolume(build.candidates.at(build.kept).shape, scene.file, probe.name);
}

int runCorrect(const CorrectOptions& o) {
  // Everything is read and checked first; the six files are written only at the end.
  const Scene scene = readSceneFile(o.scene);
  const Probe& probe = findProbe(scene, o.probe);
  const std::optional<MixingMethod> method = mixingMethodFromName(o.method);
  if (!method)
    throw InputError("--method", "expected mixing_plane or raster_convex, got '" + o.method + "'");
  const std::vector<double> c = parseNumberList(o.camera, 3, "--camera");
  const glm::dvec3 camera(c[0], c[1], c[2]);

  ReflectionPlane plane;
  if (!o.plane.empty()) {
    const std::vector<double> p = parseNumberList(o.plane, 6, "--plane");
    plane = {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}};
    if (plane.normal == glm::dvec3(0.0)) throw InputError("--plane", "the normal is zero");
  } else if (!probe.reflectionPlanes.empty()) {
    plane = probe.reflectionPlanes.front();
  } else {
    throw InputError(scene.file,
                     "probe '" + probe.name + "' has no reflection_planes; give one with --plane");
  }
  if (!(heightAbovePlaneMeters(camera, plane) > 0.0))
    throw InputError("--camera",
                     "the camera must be above the reflection plane (on the side "
                     "its normal points to)");
  if (o.out.find("{face}") == std::string::npos)
    throw InputError(o.out, "the output pattern needs {face} (px nx py ny pz nz)");
  if (!probe.cubemap) throw InputError(scene.file, "probe '" + probe.name + "' has no cubemap");
  std::filesystem::path cubemap(*probe.cubemap);
  if (cubemap.is_relative()) cubemap = scene.file.parent_path() / cubemap;
  const Cubemap source = readCubemapImage(cubemap);

  const ConvexProxy proxy = probeProxy(scene, probe, o.proxies);
  if (signedDistanceOutside(proxy.planes, probe.captureMeters) >= 0.0)
    throw InputError(scene.file, "probe '" + probe.name + "' captures outside its proxy");

  const glm::dvec3 reflected = reflectThroughPlane(camera, plane);
  const CorrectedCubemap corrected =
      correctCubemap(source, probe.captureMeters, proxy, reflected, *method);

  // `{level}` in the pattern writes every mip level; without it, level 0 only.
  const std::string levelKey = "{level}";
  const std::size_t levelAt = o.out.find(levelKey);
  const int levels = levelAt == std::string::npos ? 1 : corrected.cube.numLevels();
  for (int level = 0; level < levels; ++level) {
    std::string pattern = o.out;
    if (levelAt != std::string::npos)
      pattern.replace(levelAt, levelKey.size(), std::to_string(level));
    const std::filesystem::path folder = std::filesystem::path(pattern).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder);
    writeCubemap(corrected.cube, pattern, level);
    std::cout << "wrote " << pattern << " (" << corrected.cube.faceSize(level) << " px)\n";
  }
  const ReflectedCameraCheck inside = reflectedCameraInsideProxy(camera, plane, proxy);
  std::cout << mixingMethodName(*method) << ": reflected camera (" << reflected.x << ", "
            << reflected.y << ", " << reflected.z << ") " << (inside.inside ? "inside" : "outside")
            << " the proxy, " << missCount(corrected) << " missed texels (red) over "
            << corrected.cube.numLevels() << " levels\n";
  return 0;
}

}  // namespace

Verb addCorrectVerb(CLI::App& app) {
  auto o = std::make_shared<CorrectOptions>();
  CLI::App* correct = app.add_subcommand(
      "correct",
      "Write a parallax-corrected cubemap (EXR) for a probe, camera and reflection plane");
  correct->add_option("scene", o->scene, "scene file (*.scene.json)")->required();
  correct->add_option("--probe", o->probe, "probe name")->required();
  correct->add_option("--camera", o->camera, "camera position X,Y,Z (metres, world frame)")
      ->required();
  correct->add_option("--plane", o->plane,
                      "reflection plane PX,PY,PZ,NX,NY,NZ (default: the probe's first "
                      "reflection_planes entry)");
  correct
      ->add_option("--out", o->out,
                   "output pattern with {face}, e.g. out/corrected_{face}.exr; with {level} "
                   "too every mip level is written, else level 0")
      ->required();
  correct->add_option("--method", o->method, "mixing_plane (per texel) or raster_convex")
      ->capture_default_str();
  correct->add_option("--proxies", o->proxies,
                      "proxies.json written by `probeproxy build`: use its kept proxy");
  return {correct, [o] { return runCorrect(*o); }};
}

}  // namespace probeproxy::cli
