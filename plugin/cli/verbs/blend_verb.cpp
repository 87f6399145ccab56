// `probeproxy blend`: the probes that influence a point of interest, their weights (Lagarde or
// Enlighten), and their cubemaps mixed into one, every mip level (core/blend/).

#include "core/blend/blend_weights.h"
#include "core/blend/mix_cubemaps.h"
#include "core/blend/weight_picture.h"
#include "core/cube/cubemap_io.h"
#include "core/errors/input_error.h"
#include "core/image/write_png.h"
#include "geometry/scene/scene_file.h"
#include "plugin/cli/mixing_inputs.h"
#include "plugin/cli/number_list.h"
#include "plugin/cli/verb.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace probeproxy::cli {

namespace {

struct BlendVerbOptions {
  std::string scene;
  std::string at;   // X,Y,Z metres, world frame (Z up)
  std::string out;  // cubemap pattern with {face}
  std::string scheme = "lagarde";
  int maxProbes = kDefaultMaxBlendProbes;
  std::string weightsPng;
  bool json = false;
  // Parallax-correct each probe for this camera and reflection plane before mixing.
  std::string camera, plane, proxies, method = "mixing_plane";
};

constexpr char kFace[] = "{face}";

// Level 0 goes to the pattern as given; level l >= 1 to the same name with `mip<l>_` before
// the face: out/blend_{face}.exr -> out/blend_px.exr, out/blend_mip1_px.exr, ...
std::string levelPattern(const std::string& pattern, int level) {
  if (level == 0) return pattern;
  std::string p = pattern;
  std::string tag = "mip";
  tag += std::to_string(level);
  tag += "_";
  p.insert(p.find(kFace), tag);
  return p;
}

// One face's file of a six-file pattern; a single cross or equirect image is itself.
std::string faceFile(std::string pattern, const char* face) {
  const std::size_t at = pattern.find(kFace);
  return at == std::string::npos ? pattern : pattern.replace(at, sizeof(kFace) - 1, face);
}

std::string pointText(glm::dvec3 p) {
  std::ostringstream s;
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

int runBlend(const BlendVerbOptions& o) {
  if (o.out.empty() && o.weightsPng.empty()) {
    throw InputError("--out",
                     "nothing to write: give --out PATTERN.exr, --weights-png FILE or both");
  }
  if (!o.out.empty() && o.out.find(kFace) == std::string::npos) {
    throw InputError(o.out, "output pattern has no {face} (e.g. out/blend_{face}.exr)");
  }
  const std::vector<double> xyz = parseNumberList(o.at, 3, "--at");
  const glm::dvec3 at(xyz[0], xyz[1], xyz[2]);
  const Scene scene = readSceneFile(o.scene);
  std::vector<InfluenceVolume> volumes;
  for (const Probe& p : scene.probes) volumes.push_back(p.influence);
  const BlendOptions options{*blendSchemeFromName(o.scheme), o.maxProbes};
  std::optional<glm::dvec3> camera;
  if (!o.camera.empty()) {
    const std::vector<double> c = parseNumberList(o.camera, 3, "--camera");
    camera = glm::dvec3(c[0], c[1], c[2]);
  }
  const std::optional<MixingMethod> method = mixingMethodFromName(o.method);
  if (!method)
    throw InputError("--method", "expected mixing_plane or raster_convex, got '" + o.method + "'");

  // Everything is read and checked before anything is written.
  const std::vector<ProbeWeight> weights = blendWeights(volumes, at, options);
  if (weights.empty()) {
    std::string problem = "point of interest ";
    problem += pointText(at);
    problem += " is outside every probe's influence volume";
    throw InputError(scene.file, problem);
  }
  Cubemap mixed;
  if (!o.out.empty()) {
    std::vector<Cubemap> cubes;
    std::vector<std::string> patterns;
    MixingProxies proxies(scene, o.proxies);  // read once for every probe corrected
    for (const ProbeWeight& w : weights) {
      const Probe& probe = scene.probes[w.probe];
      patterns.push_back(probeCubemapPath(scene, probe).string());
      cubes.push_back(readCubemapImage(patterns.back()));
      if (camera) {
        // Each probe seen from the reflected camera through its own proxy (seed 000's mixing
        // step), so the mix is already parallax-corrected for this camera and plane.
        cubes.back() = correctProbe(scene, probe, cubes.back(), *camera, o.plane, proxies, *method)
                           .corrected.cube;
      }
      if (!sameCubemapLayout(cubes.back(), cubes.front())) {
        std::string problem = "face size ";
        problem += std::to_string(cubes.back().faceSize());
        problem += " px differs from probe '";
        problem += scene.probes[weights.front().probe].name;
        problem += "' (";
        problem += std::to_string(cubes.front().faceSize());
        problem += " px): mixed probes must share a face size";
        throw InputError(faceFile(patterns.back(), "px"), problem);
      }
    }
    std::vector<WeightedCubemap> weighted;
    for (std::size_t i = 0; i < cubes.size(); ++i) {
      weighted.push_back({&cubes[i], static_cast<float>(weights[i].weight)});
    }
    mixed = mixCubemaps(weighted);
  }

  std::vector<std::string> written;
  if (!o.out.empty()) {
    std::filesystem::create_directories(std::filesystem::path(o.out).parent_path().empty()
                                            ? "."
                                            : std::filesystem::path(o.out).parent_path());
    for (int level = 0; level < mixed.numLevels(); ++level) {
      writeCubemap(mixed, levelPattern(o.out, level), level);
      written.push_back(levelPattern(o.out, level));
    }
  }
  if (!o.weightsPng.empty()) {
    std::vector<glm::dvec3> captures;
    for (const Probe& p : scene.probes) captures.push_back(p.captureMeters);
    const WeightPicture picture = renderWeightPicture(volumes, at.z, options, 800, captures);
    writePng(o.weightsPng, picture.width, picture.height, picture.rgb8);
    written.push_back(o.weightsPng);
  }

  if (o.json) {
    nlohmann::ordered_json report;
    report["at"] = {at.x, at.y, at.z};
    report["scheme"] = o.scheme;
    report["max_probes"] = o.maxProbes;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ProbeWeight& w : weights) {
      list.push_back({{"probe", scene.probes[w.probe].name}, {"weight", w.weight}});
    }
    report["weights"] = list;
    report["face_size"] =
        o.out.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(mixed.faceSize());
    report["levels"] =
        o.out.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(mixed.numLevels());
    report["files"] = written;
    std::cout << report.dump(2) << "\n";
  } else {
    for (const ProbeWeight& w : weights) {
      std::cout << scene.probes[w.probe].name << " " << w.weight << "\n";
    }
    for (const std::string& f : written) std::cout << "wrote " << f << "\n";
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
                   "mixed cubemap, a pattern with {face}: level 0 there, level l as mip<l>_{face}");
  verb->add_option("--scheme", o->scheme,
                   "blend weights: lagarde (seed 000) or enlighten (seed 004)")
      ->capture_default_str()
      ->check(CLI::IsMember({"lagarde", "enlighten"}));
  verb->add_option("--max-probes", o->maxProbes, "mix at most this many probes (the N-th fades)")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
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
