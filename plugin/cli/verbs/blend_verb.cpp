// `probeproxy blend`: flags into the blend job (plugin/jobs/blend/): the probes that influence
// a point of interest, their weights, their cubemaps mixed into one.

#include "core/errors/input_error.h"
#include "plugin/cli/command_line_values.h"
#include "plugin/cli/verb.h"
#include "plugin/jobs/blend/blend_job.h"

#include <iostream>
#include <memory>
#include <string>

namespace probeproxy::cli {

namespace {

struct BlendVerbOptions {
  std::string scene, at, out, weightsPng, camera, plane, proxies;
  std::string scheme = "lagarde", method = "mixing_plane";
  int maxProbes = kDefaultMaxBlendProbes;
  bool json = false;
};

int runBlend(const BlendVerbOptions& o) {
  jobs::BlendJobOptions job;
  job.scene = o.scene;
  job.atMeters = parsePoint(o.at, "--at");
  job.outPattern = o.out;
  job.weightsPng = o.weightsPng;
  const std::optional<BlendScheme> scheme = blendSchemeFromName(o.scheme);
  if (!scheme)
    throw InputError("--scheme", "expected lagarde or enlighten, got '" + o.scheme + "'");
  job.blend = {*scheme, o.maxProbes};
  if (!o.camera.empty()) job.cameraMeters = parsePoint(o.camera, "--camera");
  job.plane = parseOptionalPlane(o.plane, "--plane");
  job.proxiesJson = o.proxies;
  job.method = parseMixingMethod(o.method);
  const jobs::BlendJobResult r = jobs::runBlendJob(job);
  if (o.json) {
    std::cout << jobs::blendReportJson(job, r);
  } else {
    for (std::size_t i = 0; i < r.weights.size(); ++i)
      std::cout << r.probes[i] << " " << r.weights[i].weight << "\n";
    for (const std::string& f : r.written) std::cout << "wrote " << f << "\n";
  }
  return 0;
}

}  // namespace

Verb addBlendVerb(CLI::App& app) {
  auto o = std::make_shared<BlendVerbOptions>();
  CLI::App* verb = app.add_subcommand(
      "blend", "Mix the probes that influence a point of interest into one cubemap");
  verb->add_option("scene", o->scene, "scene file (*.scene.json)")->required();
  verb->add_option("--at", o->at, "point of interest X,Y,Z (metres, world frame)")->required();
  verb->add_option("--out", o->out,
                   "mixed cubemap, a pattern with {face}: level 0 there, level l as mip<l>_{face} "
                   "(without --out or --weights-png, only the weights are printed)");
  verb->add_option("--scheme", o->scheme,
                   "blend weights: lagarde (Lagarde & Zanuttini 2012) or enlighten (the Enlighten "
                   "documentation)")
      ->capture_default_str();
  verb->add_option("--max-probes", o->maxProbes,
                   "mix at most this many probes (1-64; the N-th fades)")
      ->capture_default_str();
  verb->add_option(
      "--weights-png", o->weightsPng,
      "also write the top-down weight picture (PNG) of the level at the point's height");
  verb->add_flag("--json", o->json, "print the weights and files as JSON on stdout");
  verb->add_option("--camera", o->camera,
                   "parallax-correct every mixed probe first for a camera at X,Y,Z over a "
                   "reflection plane (the mixing step of `probeproxy correct`)");
  verb->add_option("--plane", o->plane,
                   "with --camera: reflection plane PX,PY,PZ,NX,NY,NZ (default: each probe's "
                   "first reflection_planes entry)");
  verb->add_option("--proxies", o->proxies,
                   "with --camera: proxies.json written by `probeproxy build`: use its kept "
                   "proxies");
  verb->add_option("--method", o->method, "with --camera: mixing_plane or raster_convex")
      ->capture_default_str();
  return {verb, [o] { return runBlend(*o); }};
}

}  // namespace probeproxy::cli
