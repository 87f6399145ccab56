#include "plugin/jobs/correct/correct_job.h"

#include "core/cube/cube_face.h"
#include "core/cube/cubemap_io.h"
#include "core/cube/write_depth_cube.h"
#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"
#include "core/io/output_folder.h"
#include "core/measures/error_images.h"
#include "core/mixing/reflected_camera.h"
#include "geometry/scene/scene_file.h"
#include "plugin/jobs/mixing/mixing_inputs.h"

namespace probeproxy::jobs {

void CorrectJobOptions::check() const {
  if (outPattern.find("{face}") == std::string::npos)
    throw InputError(outPattern, "the output pattern needs {face} (px nx py ny pz nz)");
  checkOutputFolder(std::filesystem::path(outPattern).parent_path());
}

CorrectJobResult runCorrectJob(const CorrectJobOptions& o) {
  o.check();
  // Everything is read and checked first; the files are written only at the end.
  const Scene scene = readSceneFile(o.scene);
  const Probe& probe = findProbe(scene, o.probe);
  const Cubemap source = readCubemapImage(probeCubemapPath(scene, probe));
  MixingProxies proxies(scene, o.proxiesJson.string());
  const ProbeCorrection c =
      correctProbe(scene, probe, source, o.cameraMeters, o.plane, proxies, o.method);
  const CorrectedCubemap& corrected = c.corrected;

  CorrectJobResult result;
  // `{level}` in the pattern writes every mip level; without it, level 0 only.
  const std::string levelKey = "{level}";
  const std::size_t levelAt = o.outPattern.find(levelKey);
  const int levels = levelAt == std::string::npos ? 1 : corrected.cube.numLevels();
  const auto patternOf = [&](int level) {
    std::string pattern = o.outPattern;
    if (levelAt != std::string::npos)
      pattern.replace(levelAt, levelKey.size(), std::to_string(level));
    return pattern;
  };
  // The miss mask, face by face, as `bench` draws it (writeMissMaskPng): red where the
  // texel's ray leaves no proxy face.
  const auto maskPatternOf = [](const std::string& pattern) {
    std::filesystem::path maskPattern(pattern);
    maskPattern.replace_extension();
    return maskPattern.string() + "_miss.png";
  };
  std::vector<std::filesystem::path> targets;
  for (int level = 0; level < levels; ++level) {
    for (int face = 0; face < kCubeFaceCount; ++face) {
      targets.push_back(cubeFacePath(patternOf(level), CubeFace(face)));
      targets.push_back(cubeFacePath(maskPatternOf(patternOf(level)), CubeFace(face)));
    }
  }
  requireReplaceableFiles(targets);
  for (int level = 0; level < levels; ++level) {
    const std::string pattern = patternOf(level);
    const std::filesystem::path folder = std::filesystem::path(pattern).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder);
    writeCubemap(corrected.cube, pattern, level);
    result.written.push_back(pattern);
    result.faceSizes.push_back(corrected.cube.faceSize(level));
    const std::string maskNames = maskPatternOf(pattern);
    const int size = corrected.cube.faceSize(level);
    const std::vector<std::uint8_t> everyTexel(static_cast<std::size_t>(size) * size, 1);
    for (int face = 0; face < kCubeFaceCount; ++face) {
      writeMissMaskPng(cubeFacePath(maskNames, CubeFace(face)), size, size, everyTexel,
                       corrected.missMask[level][face]);
    }
    result.missMasks.push_back(maskNames);
  }
  result.reflectedCameraMeters = c.reflectedCameraMeters;
  result.reflectedCameraInsideProxy =
      reflectedCameraInsideProxy(o.cameraMeters, c.plane, c.proxy).inside;
  result.missedTexels = missCount(corrected);
  result.levels = corrected.cube.numLevels();
  return result;
}

}  // namespace probeproxy::jobs
