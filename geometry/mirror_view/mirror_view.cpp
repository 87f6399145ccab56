#include "geometry/mirror_view/mirror_view.h"

#include "core/errors/input_error.h"
#include "core/io/regular_file.h"
#include "geometry/scene/json_document.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace probeproxy {

namespace {

struct Reader {
  const std::filesystem::path& file;
  const nlohmann::json& root;

  [[noreturn]] void fail(const std::string& path, const std::string& expected) const {
    throw InputError(file, path + ": expected " + expected);
  }

  const nlohmann::json& member(const nlohmann::json& object, const std::string& objectPath,
                               const std::string& key, const std::string& expected) const {
    if (!object.is_object() || !object.contains(key)) {
      fail(jsonMemberPath(objectPath, key), expected);
    }
    return object.at(key);
  }

  double number(const nlohmann::json& object, const std::string& objectPath,
                const std::string& key) const {
    const nlohmann::json& v = member(object, objectPath, key, "a number");
    if (!v.is_number()) fail(jsonMemberPath(objectPath, key), "a number, got " + describeJson(v));
    return v.get<double>();
  }

  int positiveInt(const std::string& key) const {
    const nlohmann::json& v = member(root, "$", key, "a positive integer");
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1 << 16) {
      fail(jsonMemberPath("$", key), "a positive integer, got " + describeJson(v));
    }
    return v.get<int>();
  }

  std::string text(const std::string& key) const {
    const nlohmann::json& v = member(root, "$", key, "a string");
    if (!v.is_string() || v.get<std::string>().empty()) {
      fail(jsonMemberPath("$", key), "a non-empty string, got " + describeJson(v));
    }
    return v.get<std::string>();
  }

  glm::dvec3 vec3(const nlohmann::json& object, const std::string& objectPath,
                  const std::string& key, bool unit) const {
    const std::string path = jsonMemberPath(objectPath, key);
    const std::string expected = unit ? "a unit vector [x, y, z]" : "[x, y, z]";
    const nlohmann::json& v = member(object, objectPath, key, expected);
    if (!v.is_array() || v.size() != 3) fail(path, expected + ", got " + describeJson(v));
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number()) fail(path, expected + ", got " + describeJson(v));
      out[i] = v[i].get<double>();
    }
    // The suite writes 6 decimals: a unit vector is unit to about 1e-6.
    if (unit && std::abs(glm::length(out) - 1.0) > 1e-4) {
      fail(path, expected + ", got " + describeJson(v));
    }
    return unit ? glm::normalize(out) : out;
  }
};

std::string readText(const std::filesystem::path& file) {
  requireRegularFile(file, "mirror view file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open mirror view file");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace

MirrorView readMirrorView(const std::filesystem::path& file) {
  nlohmann::json root;
  try {
    root = parseJsonDocument(readText(file));
  } catch (const JsonProblem& problem) {
    throw InputError(file, problem.what());
  }
  const Reader read{file, root};
  MirrorView view;
  view.name = read.text("name");
  view.probe = read.text("probe");
  view.image = file.parent_path() / read.text("image");
  view.positionImage = file.parent_path() / (view.name + "_position.exr");
  view.width = read.positiveInt("width");
  view.height = read.positiveInt("height");
  view.positionMeters = read.vec3(root, "$", "position", false);
  view.forward = read.vec3(root, "$", "forward", true);
  view.up = read.vec3(root, "$", "up", true);
  if (std::abs(glm::dot(view.forward, view.up)) > 1e-4) {
    read.fail("$.up", "a vector orthogonal to $.forward");
  }
  view.up = glm::normalize(view.up - glm::dot(view.up, view.forward) * view.forward);
  view.fovXDeg = read.number(root, "$", "fov_x_deg");
  if (!(view.fovXDeg > 0.0 && view.fovXDeg < 180.0)) {
    read.fail("$.fov_x_deg", "a field of view between 0 and 180 degrees");
  }
  const nlohmann::json& plane = read.member(root, "$", "mirror_plane", "an object");
  view.mirrorPlane.pointMeters = read.vec3(plane, "$.mirror_plane", "point", false);
  view.mirrorPlane.normal = read.vec3(plane, "$.mirror_plane", "normal", true);
  return view;
}

glm::dvec3 mirrorViewRay(const MirrorView& view, int col, int row) {
  const glm::dvec3 right = glm::cross(view.forward, view.up);
  const double tx = std::tan(glm::radians(view.fovXDeg) / 2.0);
  const double ty = tx * view.height / view.width;
  const double u = (col + 0.5) / view.width, v = (row + 0.5) / view.height;
  return glm::normalize(view.forward + (2.0 * u - 1.0) * tx * right +
                        (1.0 - 2.0 * v) * ty * view.up);
}

std::vector<std::filesystem::path> mirrorViewFiles(const Scene& scene) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path folder = scene.file.parent_path() / "mirror_views";
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

const Probe& mirrorViewProbe(const Scene& scene, const MirrorView& view) {
  for (const Probe& probe : scene.probes) {
    if (probe.name == view.probe) return probe;
  }
  throw InputError(view.image.parent_path() / (view.name + ".json"),
                   "$.probe: no probe named \"" + view.probe + "\" in " + scene.file.string());
}

}  // namespace probeproxy
