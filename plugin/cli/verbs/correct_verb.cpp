// `probeproxy correct`: the mixing step of seed 000 for one probe, camera and reflection plane,
// written as a cubemap (six EXRs) centred at the reflected camera.

#include "core/cube/cubemap_io.h"
#include "core/errors/input_error.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/mixing/reflected_camera.h"
#include "geometry/scene/scene_file.h"
#include "plugin/cli/mixing_inputs.h"
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

int runCorrect(const CorrectOptions& o) {
  // Everything is read and checked first; the six files are written only at the end.
  const Scene scene = readSceneFile(o.scene);
  const Probe& probe = findProbe(scene, o.probe);
  const std::optional<MixingMethod> method = mixingMethodFromName(o.method);
  if (!method)
    throw InputError("--method", "expected mixing_plane or raster_convex, got '" + o.method + "'");
  const std::vector<double> xyz = parseNumberList(o.camera, 3, "--camera");
  const glm::dvec3 camera(xyz[0], xyz[1], xyz[2]);

  if (o.out.find("{face}") == std::string::npos)
    throw InputError(o.out, "the output pattern needs {face} (px nx py ny pz nz)");
  const Cubemap source = readCubemapImage(probeCubemapPath(scene, probe));
  MixingProxies proxies(scene, o.proxies);
  const ProbeCorrection c = correctProbe(scene, probe, source, camera, o.plane, proxies, *method);
  const CorrectedCubemap& corrected = c.corrected;

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
  const ReflectedCameraCheck inside = reflectedCameraInsideProxy(camera, c.plane, c.proxy);
  const glm::dvec3 reflected = c.reflectedCameraMeters;
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
