#include "plugin/jobs/blend/blend_job.h"

#include "core/blend/mix_cubemaps.h"
#include "core/blend/weight_picture_legend.h"
#include "core/cube/cubemap_io.h"
#include "core/cube/write_depth_cube.h"
#include "core/errors/input_error.h"
#include "core/errors/option_checks.h"
#include "core/image/write_png.h"
#include "core/io/atomic_write.h"
#include "core/io/output_folder.h"
#include "geometry/scene/scene_file.h"
#include "plugin/jobs/mixing/mixing_inputs.h"

#include <nlohmann/json.hpp>

#include <sstream>

namespace probeproxy::jobs {

namespace {

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

// Every probe's cubemap (corrected for the camera when there is one), checked to share a face
// size, mixed by weight.
Cubemap mixProbes(const Scene& scene, const std::vector<ProbeWeight>& weights,
                  const BlendJobOptions& o) {
  std::vector<Cubemap> cubes;
  std::vector<std::string> patterns;
  MixingProxies proxies(scene, o.proxiesJson.string());  // read once for every probe corrected
  for (const ProbeWeight& w : weights) {
    const Probe& probe = scene.probes[w.probe];
    patterns.push_back(probeCubemapPath(scene, probe).string());
    cubes.push_back(readCubemapImage(patterns.back()));
    if (o.cameraMeters) {
      // Each probe seen from the reflected camera through its own proxy (Lagarde & Zanuttini's
      // mixing step), so the mix is already parallax-corrected for this camera and plane.
      cubes.back() =
          correctProbe(scene, probe, cubes.back(), *o.cameraMeters, o.plane, proxies, o.method)
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
  for (std::size_t i = 0; i < cubes.size(); ++i)
    weighted.push_back({&cubes[i], static_cast<float>(weights[i].weight)});
  return mixCubemaps(weighted);
}

}  // namespace

void BlendJobOptions::check() const {
  if (!outPattern.empty() && outPattern.find(kFace) == std::string::npos)
    throw InputError(outPattern, "output pattern has no {face} (e.g. out/blend_{face}.exr)");
  requireInRange("max_probes", blend.maxProbes, 1, 64);
  if (!outPattern.empty()) checkOutputFolder(std::filesystem::path(outPattern).parent_path());
  if (!weightsPng.empty()) checkOutputFolder(weightsPng.parent_path());
}

BlendJobResult runBlendJob(const BlendJobOptions& o) {
  o.check();
  const Scene scene = readSceneFile(o.scene);
  std::vector<InfluenceVolume> volumes;
  for (const Probe& p : scene.probes) volumes.push_back(p.influence);

  // Everything is read and checked before anything is written.
  BlendJobResult result;
  result.weights = blendWeights(volumes, o.atMeters, o.blend);
  if (result.weights.empty()) {
    throw InputError(scene.file, "point of interest " + pointText(o.atMeters) +
                                     " is outside every probe's influence volume");
  }
  for (const ProbeWeight& w : result.weights) result.probes.push_back(scene.probes[w.probe].name);
  Cubemap mixed;
  if (!o.outPattern.empty()) mixed = mixProbes(scene, result.weights, o);

  std::vector<std::filesystem::path> targets;
  for (int level = 0; !o.outPattern.empty() && level < mixed.numLevels(); ++level)
    for (int face = 0; face < kCubeFaceCount; ++face)
      targets.push_back(cubeFacePath(levelPattern(o.outPattern, level), CubeFace(face)));
  if (!o.weightsPng.empty()) targets.push_back(o.weightsPng);
  requireReplaceableFiles(targets);
  if (!o.outPattern.empty()) {
    const std::filesystem::path folder = std::filesystem::path(o.outPattern).parent_path();
    std::filesystem::create_directories(folder.empty() ? "." : folder);
    for (int level = 0; level < mixed.numLevels(); ++level) {
      writeCubemap(mixed, levelPattern(o.outPattern, level), level);
      result.written.push_back(levelPattern(o.outPattern, level));
    }
    result.faceSize = mixed.faceSize();
    result.levels = mixed.numLevels();
  }
  if (!o.weightsPng.empty()) {
    const Rgb8Canvas picture = sceneWeightPicture(scene, o.atMeters.z, o.blend);
    writePng(o.weightsPng, picture.width, picture.height, picture.rgb8);
    result.written.push_back(o.weightsPng.string());
  }
  return result;
}

std::string blendReportJson(const BlendJobOptions& o, const BlendJobResult& r) {
  nlohmann::ordered_json report;
  report["at"] = {o.atMeters.x, o.atMeters.y, o.atMeters.z};
  report["scheme"] = blendSchemeName(o.blend.scheme);
  report["max_probes"] = o.blend.maxProbes;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.weights.size(); ++i)
    list.push_back({{"probe", r.probes[i]}, {"weight", r.weights[i].weight}});
  report["weights"] = list;
  report["face_size"] = r.faceSize ? nlohmann::ordered_json(*r.faceSize) : nlohmann::ordered_json();
  report["levels"] = r.levels ? nlohmann::ordered_json(*r.levels) : nlohmann::ordered_json();
  report["files"] = r.written;
  return report.dump(2) + "\n";
}

}  // namespace probeproxy::jobs
