#pragma once
// The JSON reading kit of every file probeproxy reads (scene files, proxies.json): each
// function checks one value and throws JsonProblem("<path>: expected ..., got ...") for the
// first thing wrong, naming the array element where one is at fault
// (`$.probes[2].influence.center[1]: expected a finite number, got null`). The callers turn
// the JsonProblem into an InputError naming the file. Internal to geometry/.

#include "geometry/scene/json_document.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace probeproxy {

// How far from length 1 a quaternion or a plane normal may be: typed in by hand or rounded to
// a few digits by a tool, it is a rotation or a direction and is normalised; further off, it
// was meant as something else.
inline constexpr double kUnitLengthTolerance = 1e-3;

// A length already 1 to double rounding: such a vector is kept bit for bit, so what we write
// reads back exactly; only a hand-typed or rounded one is normalised.
inline bool isUnitToRounding(double length) {
  return std::abs(length - 1.0) <= 4 * std::numeric_limits<double>::epsilon();
}

[[noreturn]] void failJson(const std::string& path, const std::string& problem);
[[noreturn]] void failJsonExpected(const std::string& path, const std::string& expected,
                                   const nlohmann::json& got);

bool isFiniteNumber(const nlohmann::json& value);
double finiteNumber(const nlohmann::json& value, const std::string& path);
double positiveNumber(const nlohmann::json& value, const std::string& path);
double nonNegativeNumber(const nlohmann::json& value, const std::string& path);

glm::dvec3 finiteVec3(const nlohmann::json& value, const std::string& path);
glm::dvec3 positiveVec3(const nlohmann::json& value, const std::string& path);

// Rotations, normalised. Scene files and proxies.json write [w, x, y, z] (Blender's order);
// the engine presets write [x, y, z, w] (the engines' order).
glm::dquat unitQuaternionWxyz(const nlohmann::json& value, const std::string& path);
glm::dquat unitQuaternionXyzw(const nlohmann::json& value, const std::string& path);

template <std::size_t N>
double lengthOf(const std::array<double, N>& v) {
  double squaredLength = 0.0;
  for (double c : v) squaredLength += c * c;
  return std::sqrt(squaredLength);
}

// Divides by the largest component first, so that 1e200-sized input does not overflow the
// length. Reading and the scene writer's stability check must normalise the same way.
template <std::size_t N>
std::array<double, N> normalized(std::array<double, N> v) {
  double largest = 0.0;
  for (double c : v) largest = std::max(largest, std::abs(c));
  double squaredLength = 0.0;
  for (double& c : v) {
    c /= largest;
    squaredLength += c * c;
  }
  const double length = std::sqrt(squaredLength);
  for (double& c : v) c /= length;
  return v;
}

}  // namespace probeproxy
