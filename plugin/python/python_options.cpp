#include "plugin/python/python_options.h"

#include <pybind11/stl.h>

#include <string>
#include <vector>

namespace py = pybind11;

namespace probeproxy::python {

namespace {

py::value_error unknown(const char* what, const std::string& name) {
  std::string message = "unknown ";
  message += what;
  message += " option \"" + name + "\"";
  return py::value_error(message);
}

}  // namespace

void readBuildOptions(const py::dict& options, jobs::BuildJobOptions& job) {
  ProxyBuildOptions& o = job.proxy;
  for (auto [key, value] : options) {
    const std::string name = key.cast<std::string>();
    if (name == "tolerance_deg")
      o.toleranceDeg = value.cast<double>();
    else if (name == "max_planes")
      o.maxPlanes = value.cast<int>();
    else if (name == "max_miss_rate")
      o.maxMissRate = value.cast<double>();
    else if (name == "face_size")
      o.depthFaceSize = value.cast<int>();
    else if (name == "samples")
      o.samples.targetSamples = value.cast<std::size_t>();
    else if (name == "regenerate")
      o.regenerate = value.cast<bool>();
    else if (name == "threads")
      job.threads = value.cast<int>();
    else
      throw unknown("build", name);
  }
}

void readValidateOptions(const py::dict& options, jobs::ValidateJobOptions& job) {
  ValidateOptions& o = job.validate;
  for (auto [key, value] : options) {
    const std::string name = key.cast<std::string>();
    if (name == "tolerance_deg")
      job.given.toleranceDeg = value.cast<double>();
    else if (name == "max_overlap")
      o.maxOverlap = value.cast<int>();
    else if (name == "max_uncovered_m2")
      o.maxUncoveredFloorSquareMeters = value.cast<double>();
    else if (name == "max_leak_share")
      o.maxLeakShare = value.cast<double>();
    else if (name == "max_inner_overlap_m3")
      o.maxInnerOverlapCubicMeters = value.cast<double>();
    else if (name == "max_weight_jump")
      o.maxWeightJumpPerCentimeter = value.cast<double>();
    else if (name == "glossy")
      o.glossyReceivers = value.cast<bool>();
    else if (name == "grid")
      job.given.gridSpacingMeters = value.cast<double>();
    else if (name == "samples")
      o.samples.targetSamples = value.cast<std::size_t>();
    else if (name == "rules")
      o.rules = value.cast<std::vector<std::string>>();
    else if (name == "threads")
      job.threads = value.cast<int>();
    else
      throw unknown("validate", name);
  }
}

void readLayoutOptions(const py::dict& options, jobs::LayoutJobOptions& job) {
  LayoutOptions& o = job.layout;
  for (auto [key, value] : options) {
    const std::string name = key.cast<std::string>();
    if (name == "tolerance_deg")
      job.given.toleranceDeg = value.cast<double>();
    else if (name == "max_probes")
      o.maxProbes = value.cast<std::size_t>();
    else if (name == "spacing")
      o.spacingMeters = value.cast<double>();
    else if (name == "max_candidates")
      o.maxCandidates = value.cast<std::size_t>();
    else if (name == "reach")
      o.reachMeters = value.cast<double>();
    else if (name == "capture_height") {
      o.captureHeightMeters = value.cast<double>();
      job.captureHeightGiven = true;
    } else if (name == "blend_band")
      o.blendBandMeters = value.cast<double>();
    else if (name == "tile_size")
      o.tileMeters = value.cast<double>();
    else if (name == "threads")
      job.threads = value.cast<int>();
    else
      throw unknown("layout", name);
  }
}

}  // namespace probeproxy::python
