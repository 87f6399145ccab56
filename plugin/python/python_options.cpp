#include "plugin/python/python_options.h"

#include <string>

namespace py = pybind11;

namespace probeproxy::python {

namespace {

std::string text(const py::handle& value) { return py::str(value).cast<std::string>(); }

// The value of option `name`, refused outside [low, high] as the CLI's check refuses it.
template <typename T>
T inRange(const std::string& name, const py::handle& value, T low, T high) {
  const T v = value.cast<T>();
  if (!(v >= low && v <= high))
    throw py::value_error("option " + name + " = " + text(value) + " is outside [" +
                          text(py::cast(low)) + ", " + text(py::cast(high)) + "]");
  return v;
}

template <typename T>
T positive(const std::string& name, const py::handle& value) {
  const T v = value.cast<T>();
  if (!(v > T(0)))
    throw py::value_error("option " + name + " must be positive, got " + text(value));
  return v;
}

template <typename T>
T nonNegative(const std::string& name, const py::handle& value) {
  const T v = value.cast<T>();
  if (!(v >= T(0)))
    throw py::value_error("option " + name + " must not be negative, got " + text(value));
  return v;
}

py::value_error unknown(const char* what, const std::string& name) {
  std::string message = "unknown ";
  message += what;
  message += " option \"" + name + "\"";
  return py::value_error(message);
}

}  // namespace

ProxyBuildOptions buildOptions(const py::dict& options, int& threads) {
  ProxyBuildOptions o;
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
      o.samples.targetSamples = value.cast<int>();
    else if (name == "regenerate")
      o.regenerate = value.cast<bool>();
    else if (name == "threads")
      threads = value.cast<int>();
    else
      throw unknown("build", name);
  }
  return o;
}

ValidateOptions validateOptions(const py::dict& options, int& threads) {
  ValidateOptions o;
  for (auto [key, value] : options) {
    const std::string name = key.cast<std::string>();
    if (name == "tolerance_deg")
      o.toleranceDeg = positive<double>(name, value);
    else if (name == "max_overlap")
      o.maxOverlap = inRange<int>(name, value, 1, 64);
    else if (name == "max_uncovered_m2")
      o.maxUncoveredFloorSquareMeters = nonNegative<double>(name, value);
    else if (name == "max_leak_share")
      o.maxLeakShare = inRange<double>(name, value, 0.0, 1.0);
    else if (name == "max_inner_overlap_m3")
      o.maxInnerOverlapCubicMeters = nonNegative<double>(name, value);
    else if (name == "max_weight_jump")
      o.maxWeightJumpPerCentimeter = positive<double>(name, value);
    else if (name == "glossy")
      o.glossyReceivers = value.cast<bool>();
    else if (name == "grid")
      o.gridSpacingMeters = inRange<double>(name, value, 0.01, 10.0);
    else if (name == "samples")
      o.samples.targetSamples = inRange<int>(name, value, 64, 1000000);
    else if (name == "threads")
      threads = value.cast<int>();
    else
      throw unknown("validate", name);
  }
  return o;
}

}  // namespace probeproxy::python
