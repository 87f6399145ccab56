#pragma once
// `blend`: the probes that influence a point of interest, their weights (Lagarde or
// Enlighten, core/blend/), their cubemaps mixed into one at every mip level (optionally each
// parallax-corrected first for a camera by the mixing step), and the top-down weight picture.

#include "core/blend/blend_weights.h"
#include "core/mixing/corrected_cubemap.h"
#include "core/scene/probe.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace probeproxy::jobs {

struct BlendJobOptions {
  std::filesystem::path scene;
  glm::dvec3 atMeters{0.0};  // point of interest, world frame
  std::string outPattern;    // mixed cubemap with {face}: level l >= 1 as mip<l>_{face}; or empty
  std::filesystem::path weightsPng;  // top-down weight picture at the point's height; or empty
  BlendOptions blend;
  // Parallax-correct each probe for this camera and reflection plane before mixing.
  std::optional<glm::dvec3> cameraMeters;
  std::optional<ReflectionPlane> plane;  // default: each probe's first reflection_planes entry
  std::filesystem::path proxiesJson;     // with a camera: a build's export, its kept proxies
  MixingMethod method = MixingMethod::MixingPlane;

  // Throws InputError: a pattern without {face}, max_probes outside [1, 64]. With neither
  // output the job only weighs the probes.
  void check() const;
};

struct BlendJobResult {
  std::vector<std::string> probes;  // names, in the order of `weights`
  std::vector<ProbeWeight> weights;
  std::optional<int> faceSize, levels;  // of the mixed cubemap, when one was written
  std::vector<std::string> written;
};

BlendJobResult runBlendJob(const BlendJobOptions& options);

// The `blend --json` report: {"at", "scheme", "max_probes", "weights": [{"probe", "weight"}],
// "face_size", "levels", "files"}.
std::string blendReportJson(const BlendJobOptions& options, const BlendJobResult& result);

}  // namespace probeproxy::jobs
