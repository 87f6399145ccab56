// `probeproxy correct`: flags into the correct job (plugin/jobs/correct/): Lagarde & Zanuttini's
// mixing step for one probe, camera and reflection plane, written as a cubemap.

#include "plugin/cli/command_line_values.h"
#include "plugin/cli/verb.h"
#include "plugin/jobs/correct/correct_job.h"

#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace probeproxy::cli {

namespace {

struct CorrectVerbOptions {
  std::string scene, probe, camera, plane, out, method = "mixing_plane", proxies;
};

int runCorrect(const CorrectVerbOptions& o) {
  jobs::CorrectJobOptions job;
  job.scene = o.scene;
  job.probe = o.probe;
  job.cameraMeters = parsePoint(o.camera, "--camera");
  job.plane = parseOptionalPlane(o.plane, "--plane");
  job.outPattern = o.out;
  job.method = parseMixingMethod(o.method);
  job.proxiesJson = o.proxies;
  const jobs::CorrectJobResult r = jobs::runCorrectJob(job);
  for (std::size_t i = 0; i < r.written.size(); ++i)
    std::cout << "wrote " << r.written[i] << " (" << r.faceSizes[i] << " px), miss mask "
              << r.missMasks[i] << "\n";
  const glm::dvec3 reflected = r.reflectedCameraMeters;
  std::cout << o.method << ": reflected camera (" << reflected.x << ", " << reflected.y << ", "
            << reflected.z << ") " << (r.reflectedCameraInsideProxy ? "inside" : "outside")
            << " the proxy; ";
  // A texel whose ray from the reflected camera leaves no proxy face has nothing to show: the
  // method paints it red, as the talk does, so that an artist sees where the proxy falls short.
  std::size_t texels = 0;
  for (int level = 0; level < r.levels && !r.faceSizes.empty(); ++level)
    texels += 6 * std::size_t(r.faceSizes[0] >> level) * std::size_t(r.faceSizes[0] >> level);
  if (r.missedTexels == 0) {
    std::cout << "every texel of the " << r.levels << " levels sees a proxy face\n";
  } else {
    std::cout << r.missedTexels << " of " << texels << " texels (" << std::fixed
              << std::setprecision(1) << 100.0 * double(r.missedTexels) / double(texels)
              << "%) over " << r.levels
              << " levels see no proxy face from it and are painted red (the _miss.png masks): "
                 "keep the reflected camera inside the proxy (validate's "
                 "reflected_camera_outside_proxy)\n";
  }
  return 0;
}

}  // namespace

Verb addCorrectVerb(CLI::App& app) {
  auto o = std::make_shared<CorrectVerbOptions>();
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
