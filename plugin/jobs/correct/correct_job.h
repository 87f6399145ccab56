#pragma once
// `correct`: Lagarde & Zanuttini's mixing step for one probe, camera and reflection plane, written
// as a cubemap (six EXRs) centred at the reflected camera, one mip level or all of them.

#include "core/mixing/corrected_cubemap.h"
#include "core/scene/probe.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace probeproxy::jobs {

struct CorrectJobOptions {
  std::filesystem::path scene;
  std::string probe;
  glm::dvec3 cameraMeters{0.0};          // world frame
  std::optional<ReflectionPlane> plane;  // default: the probe's first reflection_planes entry
  std::string outPattern;                // needs {face}; with {level} every mip level is written
  MixingMethod method = MixingMethod::MixingPlane;
  std::filesystem::path proxiesJson;  // a build's export: use its kept proxy; empty: the
                                      // scene's proxy (built now where it is `auto`)

  void check() const;  // throws InputError: a pattern without {face}
};

struct CorrectJobResult {
  std::vector<std::string> written;  // one pattern per mip level written
  std::vector<int> faceSizes;        // px, per file pattern written
  // Per level written, the miss masks' pattern ({face} kept): the output's name with
  // `_miss.png` for its extension; missed texels pure red, the others white (as `bench`).
  std::vector<std::string> missMasks;
  glm::dvec3 reflectedCameraMeters{0.0};
  bool reflectedCameraInsideProxy = false;
  std::size_t missedTexels = 0;  // over every level (drawn red)
  int levels = 0;                // mip levels of the corrected cubemap
};

CorrectJobResult runCorrectJob(const CorrectJobOptions& options);

}  // namespace probeproxy::jobs
