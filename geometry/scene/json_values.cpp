#include "geometry/scene/json_values.h"

namespace probeproxy {

namespace {

using Json = nlohmann::json;

// The array's shape first (naming the whole array), then each element (naming it), so a user
// is pointed at the one number to fix.
template <std::size_t N>
std::array<double, N> numbersOf(const Json& value, const std::string& path, const char* elementKind,
                                bool positive) {
  if (!value.is_array() || value.size() != N) {
    failJsonExpected(path, "an array of " + std::to_string(N) + " " + elementKind, value);
  }
  std::array<double, N> numbers{};
  for (std::size_t i = 0; i < N; ++i) {
    const std::string elementPath = jsonIndexPath(path, i);
    numbers[i] =
        positive ? positiveNumber(value[i], elementPath) : finiteNumber(value[i], elementPath);
  }
  return numbers;
}

std::array<double, 4> unitQuaternionNumbers(const Json& value, const std::string& path,
                                            const char* order) {
  const auto c = numbersOf<4>(value, path, "finite numbers", false);
  if (!(std::abs(lengthOf(c) - 1.0) <= kUnitLengthTolerance)) {
    failJsonExpected(path, std::string("a unit quaternion ") + order + " (length within 1e-3 of 1)",
                     value);
  }
  return isUnitToRounding(lengthOf(c)) ? c : normalized(c);
}

glm::dquat quaternion(double w, double x, double y, double z) {
  glm::dquat q;  // members, not the constructor: its argument order depends on GLM's config
  q.w = w;
  q.x = x;
  q.y = y;
  q.z = z;
  return q;
}

}  // namespace

void failJson(const std::string& path, const std::string& problem) {
  throw JsonProblem(path + ": " + problem);
}

void failJsonExpected(const std::string& path, const std::string& expected, const Json& got) {
  failJson(path, "expected " + expected + ", got " + describeJson(got));
}

bool isFiniteNumber(const Json& value) {
  return value.is_number() && std::isfinite(value.get<double>());
}

double finiteNumber(const Json& value, const std::string& path) {
  if (!isFiniteNumber(value)) failJsonExpected(path, "a finite number", value);
  return value.get<double>();
}

double positiveNumber(const Json& value, const std::string& path) {
  if (!isFiniteNumber(value) || !(value.get<double>() > 0.0)) {
    failJsonExpected(path, "a positive number", value);
  }
  return value.get<double>();
}

double nonNegativeNumber(const Json& value, const std::string& path) {
  if (!isFiniteNumber(value) || !(value.get<double>() >= 0.0)) {
    failJsonExpected(path, "a number >= 0", value);
  }
  return value.get<double>();
}

glm::dvec3 finiteVec3(const Json& value, const std::string& path) {
  const auto c = numbersOf<3>(value, path, "finite numbers", false);
  return {c[0], c[1], c[2]};
}

glm::dvec3 positiveVec3(const Json& value, const std::string& path) {
  const auto c = numbersOf<3>(value, path, "positive numbers", true);
  return {c[0], c[1], c[2]};
}

glm::dquat unitQuaternionWxyz(const Json& value, const std::string& path) {
  const auto c = unitQuaternionNumbers(value, path, "[w, x, y, z]");
  return quaternion(c[0], c[1], c[2], c[3]);
}

glm::dquat unitQuaternionXyzw(const Json& value, const std::string& path) {
  const auto c = unitQuaternionNumbers(value, path, "[x, y, z, w]");
  return quaternion(c[3], c[0], c[1], c[2]);
}

}  // namespace probeproxy
