#include "geometry/scene/scene_file.h"

#include "core/errors/input_error.h"
#include "core/io/atomic_write.h"
#include "core/scene/file_frame.h"
#include "geometry/scene/json_document.h"
#include "geometry/scene/json_layout.h"
#include "geometry/scene/json_values.h"

#include <glm/vector_relational.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>

namespace probeproxy {

namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

constexpr int kFormatVersion = 1;
constexpr char kMeshExtensionsText[] = ".glb, .gltf, .obj, .ply or .off";
constexpr char kFacePlaceholder[] = "{face}";

// ------------------------------------------------------------------------------------------
// Shared by reading and writing.

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool hasMeshExtension(const fs::path& mesh) {
  const std::string extension = lowercase(mesh.extension().string());
  return extension == ".glb" || extension == ".gltf" || extension == ".obj" ||
         extension == ".ply" || extension == ".off";
}

bool hasExtension(const fs::path& file, const char* extension) {
  return lowercase(file.extension().string()) == extension;
}

// Quake 3 levels: a .bsp, or a .pk3 archive with the .bsp named by "map". They fix their
// own frame (Z up, 1/32 m per unit), so they take no "up". Only the level takes them: a
// convex proxy is a mesh.
bool isBspLevel(const fs::path& mesh) {
  return hasExtension(mesh, ".bsp") || hasExtension(mesh, ".pk3");
}

// The glTF 2.0 specification fixes +Y up, and Blender's exporter converts to it; other
// formats carry no up axis, so they are taken to be in the scene's frame.
UpAxis defaultMeshUp(const fs::path& mesh, UpAxis sceneUp) {
  const std::string extension = lowercase(mesh.extension().string());
  if (isBspLevel(mesh)) return UpAxis::Z;
  return extension == ".glb" || extension == ".gltf" ? UpAxis::Y : sceneUp;
}

std::array<double, 4> wxyz(const glm::dquat& q) { return {q.w, q.x, q.y, q.z}; }

// ------------------------------------------------------------------------------------------
// Reading. Each function checks one value and throws JsonProblem("<path>: ...") for the first
// thing wrong; parseSceneFile turns that into an InputError naming the file.

std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

void requireObject(const Json& value, const std::string& path) {
  if (!value.is_object()) failJsonExpected(path, "an object", value);
}

const Json& requiredMember(const Json& object, const std::string& path, const char* name) {
  const auto member = object.find(name);
  if (member == object.end()) failJson(path, "expected member " + quoted(name));
  return *member;
}

const Json* optionalMember(const Json& object, const char* name) {
  const auto member = object.find(name);
  return member == object.end() ? nullptr : &*member;
}

// Levenshtein distance, ignoring case: `Capture` and `captur` are typos of `capture`.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + !same});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::optional<std::string_view> closestName(std::string_view typed,
                                            std::initializer_list<std::string_view> known) {
  std::optional<std::string_view> best;
  std::size_t bestDistance = 0;
  for (std::string_view name : known) {
    const std::size_t distance = editDistance(typed, name);
    // Short names are close to everything; allow about a third of the name to be wrong.
    const std::size_t allowed = name.size() <= 3 ? 1 : std::max<std::size_t>(2, name.size() / 3);
    if (distance <= allowed && (!best || distance < bestDistance)) {
      best = name;
      bestDistance = distance;
    }
  }
  return best;
}

void rejectUnknownMembers(const Json& object, const std::string& path,
                          std::initializer_list<std::string_view> known) {
  for (const auto& [name, value] : object.items()) {
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string hint;
    if (const auto suggestion = closestName(name, known)) {
      hint = "did you mean " + quoted(*suggestion) + "?";
    } else {
      hint = "expected one of";
      for (std::string_view option : known) {
        hint += (option == *known.begin() ? " " : ", ") + quoted(option);
      }
    }
    failJson(jsonMemberPath(path, name), "unknown member (" + hint + ")");
  }
}

void checkVersion(const Json& root) {
  const Json& version = requiredMember(root, "$", "probeproxy_scene");
  if (!version.is_number() || version.get<double>() != kFormatVersion) {
    failJsonExpected("$.probeproxy_scene", std::to_string(kFormatVersion), version);
  }
}

UpAxis upAxis(const Json& value, const std::string& path) {
  if (value == "Y") return UpAxis::Y;
  if (value == "Z") return UpAxis::Z;
  failJsonExpected(path, "\"Y\" or \"Z\"", value);
}

glm::dvec3 unitDirection(const Json& value, const std::string& path) {
  const glm::dvec3 v = finiteVec3(value, path);
  if (v == glm::dvec3(0.0)) {
    failJsonExpected(path, "a non-zero direction (an array of 3 finite numbers)", value);
  }
  const auto unit = normalized(std::array<double, 3>{v.x, v.y, v.z});
  return {unit[0], unit[1], unit[2]};
}

std::string nonEmptyString(const Json& value, const std::string& path) {
  if (!value.is_string() || value.get_ref<const std::string&>().empty()) {
    failJsonExpected(path, "a non-empty string", value);
  }
  return value.get<std::string>();
}

fs::path meshPathAsWritten(const Json& value, const std::string& path) {
  if (!value.is_string() || !hasMeshExtension(value.get<std::string>())) {
    failJsonExpected(path, std::string("a mesh path ending in ") + kMeshExtensionsText, value);
  }
  return fs::path(value.get<std::string>());
}

fs::path levelPathAsWritten(const Json& value, const std::string& path) {
  if (!value.is_string() || !isLevelFile(value.get<std::string>())) {
    failJsonExpected(path, std::string("a mesh path ending in ") + kLevelExtensionsText, value);
  }
  return fs::path(value.get<std::string>());
}

fs::path resolvedAgainst(const fs::path& pathAsWritten, const fs::path& folder) {
  if (pathAsWritten.is_absolute()) return pathAsWritten.lexically_normal();
  return (folder / pathAsWritten).lexically_normal();
}

// Members holding positions and sizes, read straight into metres. A number that is finite in
// file units can still overflow once scaled (a meters_per_unit of 1e300); the world may not.
bool isFinite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

[[noreturn]] void failOverflow(const std::string& path, const Json& value) {
  failJsonExpected(path, "numbers that stay finite in metres", value);
}

// Ray casting (Embree, in float relative to the level's centre), the weight grids and every
// allocation sized by the scene need numbers a level can hold: positions within
// kMaxSceneMeters of the origin and sizes up to that, in metres after meters_per_unit.
bool withinScene(const glm::dvec3& meters) {
  return std::abs(meters.x) <= kMaxSceneMeters && std::abs(meters.y) <= kMaxSceneMeters &&
         std::abs(meters.z) <= kMaxSceneMeters;
}

[[noreturn]] void failOutsideScene(const std::string& path, const Json& value, const char* what) {
  std::ostringstream expected;
  expected << what << " within " << kMaxSceneMeters << " m (the limit of a scene, in metres)";
  failJsonExpected(path, expected.str(), value);
}

glm::dvec3 pointValue(const Json& value, const std::string& path, const FileFrame& frame) {
  const glm::dvec3 meters = worldPointFromFile(frame, finiteVec3(value, path));
  if (!isFinite(meters)) failOverflow(path, value);
  if (!withinScene(meters)) failOutsideScene(path, value, "coordinates");
  return meters;
}

glm::dvec3 pointMember(const Json& object, const std::string& path, const char* name,
                       const FileFrame& frame) {
  return pointValue(requiredMember(object, path, name), jsonMemberPath(path, name), frame);
}

glm::dvec3 halfExtentsMember(const Json& object, const std::string& path, const char* name,
                             const FileFrame& frame) {
  const std::string memberPath = jsonMemberPath(path, name);
  const Json& value = requiredMember(object, path, name);
  const glm::dvec3 meters = worldHalfExtentsFromFile(frame, positiveVec3(value, memberPath));
  if (!isFinite(meters)) failOverflow(memberPath, value);
  if (!withinScene(meters)) failOutsideScene(memberPath, value, "half-extents");
  return meters;
}

double lengthMember(const Json& object, const std::string& path, const char* name,
                    const FileFrame& frame) {
  const std::string memberPath = jsonMemberPath(path, name);
  const Json& value = requiredMember(object, path, name);
  const double meters = worldLengthFromFile(frame, positiveNumber(value, memberPath));
  if (!std::isfinite(meters)) failOverflow(memberPath, value);
  if (!(meters <= kMaxSceneMeters)) failOutsideScene(memberPath, value, "a length");
  return meters;
}

// `kind` selects the member set; it must be one of `kinds`.
std::string kindOf(const Json& object, const std::string& path,
                   std::initializer_list<std::string_view> kinds, const std::string& expectedText) {
  const Json& kind = requiredMember(object, path, "kind");
  if (kind.is_string()) {
    const std::string& name = kind.get_ref<const std::string&>();
    if (std::find(kinds.begin(), kinds.end(), name) != kinds.end()) return name;
  }
  failJsonExpected(jsonMemberPath(path, "kind"), expectedText, kind);
}

// "maps/downer.bsp": a relative path inside the archive, kept as written.
fs::path mapInArchive(const Json& value, const std::string& path) {
  const bool bspName = value.is_string() && hasExtension(value.get<std::string>(), ".bsp");
  if (!bspName || fs::path(value.get<std::string>()).is_absolute()) {
    failJsonExpected(path, "the path of a .bsp inside the .pk3, e.g. \"maps/downer.bsp\"", value);
  }
  return fs::path(value.get<std::string>());
}

LevelMeshRef readLevelMesh(const Json& value, const std::string& path, UpAxis sceneUp,
                           const fs::path& folder) {
  LevelMeshRef mesh;
  if (value.is_string()) {  // "corridor.glb" is short for {"mesh": "corridor.glb"}
    mesh.pathAsWritten = levelPathAsWritten(value, path);
    if (hasExtension(mesh.pathAsWritten, ".pk3")) {
      failJsonExpected(
          path, "an object {\"mesh\": \"<archive>.pk3\", \"map\": \"maps/<name>.bsp\"}", value);
    }
  } else if (value.is_object()) {
    mesh.pathAsWritten =
        levelPathAsWritten(requiredMember(value, path, "mesh"), jsonMemberPath(path, "mesh"));
    if (hasExtension(mesh.pathAsWritten, ".pk3")) {
      rejectUnknownMembers(value, path, {"mesh", "map"});
      mesh.map = mapInArchive(requiredMember(value, path, "map"), jsonMemberPath(path, "map"));
    } else if (isBspLevel(mesh.pathAsWritten)) {
      rejectUnknownMembers(value, path, {"mesh"});
    } else {
      rejectUnknownMembers(value, path, {"mesh", "up"});
    }
    if (const Json* up = optionalMember(value, "up")) {
      mesh.up = upAxis(*up, jsonMemberPath(path, "up"));
      mesh.upWasExplicit = true;
    }
  } else {
    failJsonExpected(path, "a mesh path or an object with \"mesh\"", value);
  }
  mesh.path = resolvedAgainst(mesh.pathAsWritten, folder);
  if (!mesh.upWasExplicit) mesh.up = defaultMeshUp(mesh.pathAsWritten, sceneUp);
  return mesh;
}

std::vector<LevelMeshRef> readLevel(const Json& value, const std::string& path, UpAxis sceneUp,
                                    const fs::path& folder) {
  if (!value.is_array() || value.empty())
    failJsonExpected(path, "a non-empty array of meshes", value);
  std::vector<LevelMeshRef> level;
  for (std::size_t i = 0; i < value.size(); ++i) {
    level.push_back(readLevelMesh(value[i], jsonIndexPath(path, i), sceneUp, folder));
  }
  return level;
}

BoxInfluence readBoxInfluence(const Json& value, const std::string& path, const FileFrame& frame) {
  rejectUnknownMembers(value, path,
                       {"kind", "center", "half_extents", "rotation", "inner_half_extents"});
  BoxInfluence box;
  box.centerMeters = pointMember(value, path, "center", frame);
  box.halfExtentsMeters = halfExtentsMember(value, path, "half_extents", frame);
  const Json& halfExtentsJson = value.at("half_extents");  // checked by halfExtentsMember
  const glm::dvec3 halfExtentsInFile = finiteVec3(halfExtentsJson, "");
  glm::dquat boxToFile(1, 0, 0, 0);
  if (const Json* rotation = optionalMember(value, "rotation")) {
    boxToFile = unitQuaternionWxyz(*rotation, jsonMemberPath(path, "rotation"));
  }
  box.worldFromBox = worldRotationFromFile(frame, boxToFile);
  box.innerHalfExtentsMeters = box.halfExtentsMeters;  // no fade unless the file says so
  if (const Json* inner = optionalMember(value, "inner_half_extents")) {
    const std::string innerPath = jsonMemberPath(path, "inner_half_extents");
    const glm::dvec3 innerInFile = positiveVec3(*inner, innerPath);
    if (glm::any(glm::greaterThan(innerInFile, halfExtentsInFile))) {
      failJsonExpected(innerPath,
                       "an array of 3 positive numbers, each at most half_extents " +
                           describeJson(halfExtentsJson),
                       *inner);
    }
    box.innerHalfExtentsMeters = worldHalfExtentsFromFile(frame, innerInFile);
  }
  return box;
}

SphereInfluence readSphereInfluence(const Json& value, const std::string& path,
                                    const FileFrame& frame) {
  rejectUnknownMembers(value, path, {"kind", "center", "radius", "inner_radius"});
  SphereInfluence sphere;
  sphere.centerMeters = pointMember(value, path, "center", frame);
  sphere.radiusMeters = lengthMember(value, path, "radius", frame);
  sphere.innerRadiusMeters = sphere.radiusMeters;
  if (const Json* inner = optionalMember(value, "inner_radius")) {
    const Json& radiusJson = value.at("radius");
    if (!isFiniteNumber(*inner) || !(inner->get<double>() > 0.0) ||
        inner->get<double>() > radiusJson.get<double>()) {
      failJsonExpected(jsonMemberPath(path, "inner_radius"),
                       "a positive number at most radius " + describeJson(radiusJson), *inner);
    }
    sphere.innerRadiusMeters = worldLengthFromFile(frame, inner->get<double>());
  }
  return sphere;
}

InfluenceVolume readInfluence(const Json& value, const std::string& path, const FileFrame& frame) {
  requireObject(value, path);
  const std::string kind = kindOf(value, path, {"box", "sphere"}, "\"box\" or \"sphere\"");
  if (kind == "box") return readBoxInfluence(value, path, frame);
  return readSphereInfluence(value, path, frame);
}

ProxySpec readProxy(const Json& value, const std::string& path, const FileFrame& frame,
                    const fs::path& folder) {
  if (value == "auto") return AutoProxy{};
  if (value == "infinite") return InfiniteProxy{};
  if (!value.is_object()) failJsonExpected(path, "\"auto\", \"infinite\" or an object", value);

  const std::string kind = kindOf(value, path, {"box", "obb", "sphere", "cheap_k", "convex"},
                                  "\"box\", \"obb\", \"sphere\", \"cheap_k\" or \"convex\"");
  if (kind == "box") {
    rejectUnknownMembers(value, path, {"kind", "center", "half_extents"});
    return AuthoredBox{pointMember(value, path, "center", frame),
                       halfExtentsMember(value, path, "half_extents", frame)};
  }
  if (kind == "obb") {
    rejectUnknownMembers(value, path, {"kind", "center", "half_extents", "rotation"});
    AuthoredObb obb{pointMember(value, path, "center", frame),
                    halfExtentsMember(value, path, "half_extents", frame)};
    obb.worldFromBox =
        worldRotationFromFile(frame, unitQuaternionWxyz(requiredMember(value, path, "rotation"),
                                                        jsonMemberPath(path, "rotation")));
    return obb;
  }
  if (kind == "sphere") {
    rejectUnknownMembers(value, path, {"kind", "center", "radius"});
    return AuthoredSphere{pointMember(value, path, "center", frame),
                          lengthMember(value, path, "radius", frame)};
  }
  if (kind == "cheap_k") {
    // k is per file length unit: lookup = normalize(k * (x - C) + r) with x - C in file units.
    rejectUnknownMembers(value, path, {"kind", "k"});
    const std::string kPath = jsonMemberPath(path, "k");
    const double kPerUnit = nonNegativeNumber(requiredMember(value, path, "k"), kPath);
    const double kPerMeter = kPerUnit / worldLengthFromFile(frame, 1.0);
    if (!std::isfinite(kPerMeter)) failOverflow(kPath, value.at("k"));
    return AuthoredCheapK{kPerMeter};
  }
  rejectUnknownMembers(value, path, {"kind", "mesh"});
  AuthoredConvexMesh convex;
  convex.meshAsWritten =
      meshPathAsWritten(requiredMember(value, path, "mesh"), jsonMemberPath(path, "mesh"));
  convex.mesh = resolvedAgainst(convex.meshAsWritten, folder);
  return convex;
}

// Six files (`{face}` in the name) or one cross or equirectangular image: the image readers
// (core/cube/cubemap_io.h) take .exr, .hdr and .png.
std::string cubemapPattern(const Json& value, const std::string& path) {
  const auto isImagePath = [](const std::string& text) {
    const std::string extension = fs::path(text).extension().string();
    return extension == ".exr" || extension == ".hdr" || extension == ".png";
  };
  if (!value.is_string() || !isImagePath(value.get_ref<const std::string&>())) {
    failJsonExpected(path,
                     std::string("an .exr, .hdr or .png image path (six files with ") +
                         kFacePlaceholder + ", or one cross or equirectangular image)",
                     value);
  }
  return value.get<std::string>();
}

std::vector<ReflectionPlane> readReflectionPlanes(const Json& value, const std::string& path,
                                                  const FileFrame& frame) {
  if (!value.is_array()) failJsonExpected(path, "an array of planes", value);
  std::vector<ReflectionPlane> planes;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string planePath = jsonIndexPath(path, i);
    const Json& planeJson = value[i];
    requireObject(planeJson, planePath);
    rejectUnknownMembers(planeJson, planePath, {"point", "normal"});
    ReflectionPlane plane;
    plane.pointMeters = pointMember(planeJson, planePath, "point", frame);
    plane.normal =
        worldDirectionFromFile(frame, unitDirection(requiredMember(planeJson, planePath, "normal"),
                                                    jsonMemberPath(planePath, "normal")));
    planes.push_back(plane);
  }
  return planes;
}

Probe readProbe(const Json& value, const std::string& path, const FileFrame& frame,
                const fs::path& folder) {
  requireObject(value, path);
  rejectUnknownMembers(value, path,
                       {"name", "capture", "influence", "proxy", "cubemap", "reflection_planes"});
  Probe probe;
  probe.name = nonEmptyString(requiredMember(value, path, "name"), jsonMemberPath(path, "name"));
  probe.captureMeters = pointMember(value, path, "capture", frame);
  probe.influence = readInfluence(requiredMember(value, path, "influence"),
                                  jsonMemberPath(path, "influence"), frame);
  probe.proxy =
      readProxy(requiredMember(value, path, "proxy"), jsonMemberPath(path, "proxy"), frame, folder);
  if (const Json* cubemap = optionalMember(value, "cubemap")) {
    probe.cubemap = cubemapPattern(*cubemap, jsonMemberPath(path, "cubemap"));
  }
  if (const Json* planes = optionalMember(value, "reflection_planes")) {
    probe.reflectionPlanes =
        readReflectionPlanes(*planes, jsonMemberPath(path, "reflection_planes"), frame);
  }
  return probe;
}

std::vector<Probe> readProbes(const Json& value, const std::string& path, const FileFrame& frame,
                              const fs::path& folder) {
  if (!value.is_array()) failJsonExpected(path, "an array of probes", value);
  std::vector<Probe> probes;
  std::map<std::string, std::size_t> indexByName;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string probePath = jsonIndexPath(path, i);
    probes.push_back(readProbe(value[i], probePath, frame, folder));
    const auto [first, isNew] = indexByName.emplace(probes.back().name, i);
    if (!isNew) {
      failJson(jsonMemberPath(probePath, "name"),
               describeJson(Json(probes.back().name)) + " is used by " +
                   jsonIndexPath(path, first->second) + " already");
    }
  }
  return probes;
}

// `measured_with`: lengths in file units like every other member, seed points like captures.
MeasureSettings readMeasuredWith(const Json& value, const std::string& path,
                                 const FileFrame& frame) {
  requireObject(value, path);
  rejectUnknownMembers(
      value, path,
      {"seed_points", "grid", "step_height", "head_clearance", "eye_height", "tolerance_deg"});
  MeasureSettings m;
  if (const Json* seeds = optionalMember(value, "seed_points")) {
    const std::string seedsPath = jsonMemberPath(path, "seed_points");
    if (!seeds->is_array()) failJsonExpected(seedsPath, "an array of points", *seeds);
    for (std::size_t i = 0; i < seeds->size(); ++i)
      m.seedPointsMeters.push_back(pointValue((*seeds)[i], jsonIndexPath(seedsPath, i), frame));
  }
  const auto length = [&](const char* name, std::optional<double>& into) {
    if (optionalMember(value, name) != nullptr) into = lengthMember(value, path, name, frame);
  };
  length("grid", m.gridSpacingMeters);
  length("step_height", m.stepHeightMeters);
  length("head_clearance", m.headClearanceMeters);
  length("eye_height", m.eyeHeightMeters);
  if (const Json* tolerance = optionalMember(value, "tolerance_deg"))
    m.toleranceDeg = positiveNumber(*tolerance, jsonMemberPath(path, "tolerance_deg"));
  return m;
}

Scene sceneFromDocument(const Json& root, const fs::path& absoluteFile) {
  requireObject(root, "$");
  // The version first: a newer file may well have members this reader does not know.
  checkVersion(root);
  rejectUnknownMembers(
      root, "$", {"probeproxy_scene", "up", "meters_per_unit", "level", "probes", "measured_with"});
  Scene scene;
  scene.file = absoluteFile;
  scene.fileUp = upAxis(requiredMember(root, "$", "up"), "$.up");
  if (const Json* metersPerUnit = optionalMember(root, "meters_per_unit")) {
    scene.metersPerUnit = positiveNumber(*metersPerUnit, "$.meters_per_unit");
    if (!(scene.metersPerUnit >= kMinMetersPerUnit && scene.metersPerUnit <= kMaxMetersPerUnit)) {
      std::ostringstream expected;
      expected << "a number from " << kMinMetersPerUnit << " to " << kMaxMetersPerUnit;
      failJsonExpected("$.meters_per_unit", expected.str(), *metersPerUnit);
    }
  }
  const FileFrame frame{scene.fileUp, scene.metersPerUnit};
  const fs::path folder = absoluteFile.parent_path();
  scene.level = readLevel(requiredMember(root, "$", "level"), "$.level", scene.fileUp, folder);
  scene.probes = readProbes(requiredMember(root, "$", "probes"), "$.probes", frame, folder);
  if (const Json* measuredWith = optionalMember(root, "measured_with"))
    scene.measuredWith = readMeasuredWith(*measuredWith, "$.measured_with", frame);
  return scene;
}

// ------------------------------------------------------------------------------------------
// Writing.

using Members = std::vector<std::pair<std::string, JsonLayoutValue>>;

JsonLayoutValue numbersJson(std::initializer_list<double> numbers) {
  std::vector<JsonLayoutValue> elements;
  for (double number : numbers) elements.push_back(jsonCoordinate(number));
  return jsonArray(std::move(elements));
}

JsonLayoutValue vec3Json(const glm::dvec3& v) { return numbersJson({v.x, v.y, v.z}); }

template <std::size_t N>
std::array<double, N> roundedForJson(const std::array<double, N>& v) {
  std::array<double, N> rounded;
  for (std::size_t i = 0; i < N; ++i) rounded[i] = jsonRoundedCoordinate(v[i]);
  return rounded;
}

// The reader normalizes unit vectors and quaternions. Rounding them to the written precision
// moves their length off 1 by up to ~1e-9, enough for the re-normalized numbers to round
// differently next time; so settle on a rounding that normalizes back to itself, and
// writing, reading and writing again gives the same bytes.
template <std::size_t N>
std::array<double, N> stableUnitForJson(const std::array<double, N>& unit) {
  std::array<double, N> rounded = roundedForJson(unit);
  for (int attempt = 0; attempt < 8; ++attempt) {
    const std::array<double, N> again = roundedForJson(normalized(rounded));
    if (again == rounded) break;
    rounded = again;
  }
  return rounded;
}

JsonLayoutValue rotationJson(const glm::dquat& rotationInFile) {
  std::array<double, 4> c = wxyz(rotationInFile);
  // Only a unit quaternion is settled; anything else is written as it is, for the
  // read-back check to report.
  if (std::abs(lengthOf(c) - 1.0) <= kUnitLengthTolerance) c = stableUnitForJson(c);
  return numbersJson({c[0], c[1], c[2], c[3]});
}

JsonLayoutValue directionJson(const glm::dvec3& directionInFile) {
  std::array<double, 3> c = {directionInFile.x, directionInFile.y, directionInFile.z};
  if (lengthOf(c) > 0.0 && std::isfinite(lengthOf(c))) c = stableUnitForJson(c);
  return numbersJson({c[0], c[1], c[2]});
}

bool sameText(const JsonLayoutValue& a, const JsonLayoutValue& b) {
  if (a.elements.size() != b.elements.size()) return false;
  for (std::size_t i = 0; i < a.elements.size(); ++i) {
    if (a.elements[i].scalarText != b.elements[i].scalarText) return false;
  }
  return a.scalarText == b.scalarText;
}

JsonLayoutValue upJson(UpAxis up) { return jsonString(up == UpAxis::Y ? "Y" : "Z"); }

fs::path spelledPath(const fs::path& absolutePath, const fs::path& pathAsWritten) {
  return pathAsWritten.empty() ? absolutePath : pathAsWritten;
}

JsonLayoutValue pathJson(const fs::path& path) { return jsonString(path.generic_string()); }

JsonLayoutValue levelMeshJson(const LevelMeshRef& mesh, UpAxis sceneUp) {
  const fs::path spelled = spelledPath(mesh.path, mesh.pathAsWritten);
  Members members{{"mesh", pathJson(spelled)}};
  if (!mesh.map.empty()) members.emplace_back("map", pathJson(mesh.map));
  // A Scene built in memory may not say upWasExplicit; an up the default would not give back
  // must still be written. A BSP level has no up of its own to write: it is always Z.
  if (isBspLevel(spelled)) return jsonObject(std::move(members));
  if (mesh.upWasExplicit || mesh.up != defaultMeshUp(spelled, sceneUp)) {
    members.emplace_back("up", upJson(mesh.up));
  }
  return jsonObject(std::move(members));
}

JsonLayoutValue influenceJson(const InfluenceVolume& influence, const FileFrame& frame) {
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    const JsonLayoutValue outer = vec3Json(fileHalfExtentsFromWorld(frame, box->halfExtentsMeters));
    const JsonLayoutValue inner =
        vec3Json(fileHalfExtentsFromWorld(frame, box->innerHalfExtentsMeters));
    Members members{{"kind", jsonString("box")},
                    {"center", vec3Json(filePointFromWorld(frame, box->centerMeters))},
                    {"half_extents", outer},
                    {"rotation", rotationJson(fileRotationFromWorld(frame, box->worldFromBox))}};
    if (!sameText(inner, outer)) members.emplace_back("inner_half_extents", inner);
    return jsonObject(std::move(members));
  }
  const auto& sphere = std::get<SphereInfluence>(influence);
  const JsonLayoutValue outer = jsonCoordinate(fileLengthFromWorld(frame, sphere.radiusMeters));
  const JsonLayoutValue inner =
      jsonCoordinate(fileLengthFromWorld(frame, sphere.innerRadiusMeters));
  Members members{{"kind", jsonString("sphere")},
                  {"center", vec3Json(filePointFromWorld(frame, sphere.centerMeters))},
                  {"radius", outer}};
  if (!sameText(inner, outer)) members.emplace_back("inner_radius", inner);
  return jsonObject(std::move(members));
}

template <class... Handlers>
struct Overloaded : Handlers... {
  using Handlers::operator()...;
};
template <class... Handlers>
Overloaded(Handlers...) -> Overloaded<Handlers...>;

JsonLayoutValue proxyJson(const ProxySpec& proxy, const FileFrame& frame) {
  const auto center = [&](const glm::dvec3& centerMeters) {
    return vec3Json(filePointFromWorld(frame, centerMeters));
  };
  const auto halfExtents = [&](const glm::dvec3& halfExtentsMeters) {
    return vec3Json(fileHalfExtentsFromWorld(frame, halfExtentsMeters));
  };
  return std::visit(
      Overloaded{
          [](const AutoProxy&) { return jsonString("auto"); },
          [](const InfiniteProxy&) { return jsonString("infinite"); },
          [&](const AuthoredBox& box) {
            return jsonObject({{"kind", jsonString("box")},
                               {"center", center(box.centerMeters)},
                               {"half_extents", halfExtents(box.halfExtentsMeters)}});
          },
          [&](const AuthoredObb& obb) {
            return jsonObject(
                {{"kind", jsonString("obb")},
                 {"center", center(obb.centerMeters)},
                 {"half_extents", halfExtents(obb.halfExtentsMeters)},
                 {"rotation", rotationJson(fileRotationFromWorld(frame, obb.worldFromBox))}});
          },
          [&](const AuthoredSphere& sphere) {
            return jsonObject(
                {{"kind", jsonString("sphere")},
                 {"center", center(sphere.centerMeters)},
                 {"radius", jsonCoordinate(fileLengthFromWorld(frame, sphere.radiusMeters))}});
          },
          [&](const AuthoredCheapK& cheapK) {
            return jsonObject(
                {{"kind", jsonString("cheap_k")},
                 {"k", jsonFactor(cheapK.kPerMeter * worldLengthFromFile(frame, 1.0))}});
          },
          [&](const AuthoredConvexMesh& convex) {
            return jsonObject({{"kind", jsonString("convex")},
                               {"mesh", pathJson(spelledPath(convex.mesh, convex.meshAsWritten))}});
          },
      },
      proxy);
}

JsonLayoutValue reflectionPlanesJson(const std::vector<ReflectionPlane>& planes,
                                     const FileFrame& frame) {
  std::vector<JsonLayoutValue> elements;
  for (const ReflectionPlane& plane : planes) {
    elements.push_back(
        jsonObject({{"point", vec3Json(filePointFromWorld(frame, plane.pointMeters))},
                    {"normal", directionJson(fileDirectionFromWorld(frame, plane.normal))}}));
  }
  return jsonArray(std::move(elements));
}

JsonLayoutValue probeJson(const Probe& probe, const FileFrame& frame) {
  Members members{{"name", jsonString(probe.name)},
                  {"capture", vec3Json(filePointFromWorld(frame, probe.captureMeters))},
                  {"influence", influenceJson(probe.influence, frame)},
                  {"proxy", proxyJson(probe.proxy, frame)}};
  if (probe.cubemap) members.emplace_back("cubemap", jsonString(*probe.cubemap));
  if (!probe.reflectionPlanes.empty()) {
    members.emplace_back("reflection_planes", reflectionPlanesJson(probe.reflectionPlanes, frame));
  }
  return jsonObject(std::move(members), /*oneItemPerLine=*/true);
}

JsonLayoutValue measuredWithJson(const MeasureSettings& m, const FileFrame& frame) {
  Members members;
  if (!m.seedPointsMeters.empty()) {
    std::vector<JsonLayoutValue> seeds;
    for (const glm::dvec3& s : m.seedPointsMeters)
      seeds.push_back(vec3Json(filePointFromWorld(frame, s)));
    members.emplace_back("seed_points", jsonArray(std::move(seeds)));
  }
  const auto length = [&](const char* name, const std::optional<double>& meters) {
    if (meters) members.emplace_back(name, jsonCoordinate(fileLengthFromWorld(frame, *meters)));
  };
  length("grid", m.gridSpacingMeters);
  length("step_height", m.stepHeightMeters);
  length("head_clearance", m.headClearanceMeters);
  length("eye_height", m.eyeHeightMeters);
  if (m.toleranceDeg) members.emplace_back("tolerance_deg", jsonExactNumber(*m.toleranceDeg));
  return jsonObject(std::move(members), /*oneItemPerLine=*/true);
}

// How `absolutePath` is spelled in a file in `newFolder`: as before while that still names the
// same file, else relative to the new folder (absolute only if there is no relative way).
fs::path spellingIn(const fs::path& absolutePath, const fs::path& pathAsWritten,
                    const fs::path& oldFolder, const fs::path& newFolder) {
  if (!pathAsWritten.empty() && (pathAsWritten.is_absolute() || oldFolder == newFolder)) {
    return pathAsWritten;
  }
  if (!absolutePath.is_absolute()) return spelledPath(absolutePath, pathAsWritten);
  return absolutePath.lexically_proximate(newFolder);
}

fs::path absoluteNormal(const fs::path& file) { return fs::absolute(file).lexically_normal(); }

Scene rebasedFor(const Scene& scene, const fs::path& absoluteTarget) {
  const fs::path oldFolder =
      scene.file.empty() ? fs::path() : absoluteNormal(scene.file).parent_path();
  const fs::path newFolder = absoluteTarget.parent_path();
  Scene rebased = scene;
  rebased.file = absoluteTarget;
  for (LevelMeshRef& mesh : rebased.level) {
    mesh.pathAsWritten = spellingIn(mesh.path, mesh.pathAsWritten, oldFolder, newFolder);
  }
  for (Probe& probe : rebased.probes) {
    if (auto* convex = std::get_if<AuthoredConvexMesh>(&probe.proxy)) {
      convex->meshAsWritten = spellingIn(convex->mesh, convex->meshAsWritten, oldFolder, newFolder);
    }
    // A cubemap is a pattern (`{face}`), kept as written and read against the scene's folder.
    if (probe.cubemap && !oldFolder.empty() && fs::path(*probe.cubemap).is_relative()) {
      const fs::path images = (oldFolder / *probe.cubemap).lexically_normal();
      probe.cubemap = spellingIn(images, *probe.cubemap, oldFolder, newFolder).string();
    }
  }
  return rebased;
}

}  // namespace

Scene parseSceneFile(std::string_view bytes, const std::filesystem::path& file) {
  try {
    return sceneFromDocument(parseJsonDocument(bytes), absoluteNormal(file));
  } catch (const JsonProblem& problem) {
    throw InputError(file, problem.what());
  }
}

bool isLevelFile(const std::filesystem::path& file) {
  return hasMeshExtension(file) || isBspLevel(file);
}

Scene readSceneFile(const std::filesystem::path& file) {
  if (isLevelFile(file)) {
    throw InputError(file,
                     "is a level, not a scene file (.scene.json): list it in a scene's "
                     "\"level\", or lay it out with `probeproxy layout " +
                         file.string() + " --out DIR`, which takes a level as it is");
  }
  return parseSceneFile(readJsonFile(file), file);
}

std::string sceneFileJson(const Scene& scene) {
  const FileFrame frame{scene.fileUp, scene.metersPerUnit};
  std::vector<JsonLayoutValue> level;
  for (const LevelMeshRef& mesh : scene.level) level.push_back(levelMeshJson(mesh, scene.fileUp));
  std::vector<JsonLayoutValue> probes;
  for (const Probe& probe : scene.probes) probes.push_back(probeJson(probe, frame));
  Members members{{"probeproxy_scene", jsonInteger(kFormatVersion)},
                  {"up", upJson(scene.fileUp)},
                  {"meters_per_unit", jsonExactNumber(scene.metersPerUnit)},
                  {"level", jsonArray(std::move(level))},
                  {"probes", jsonArray(std::move(probes), /*oneItemPerLine=*/true)}};
  if (!scene.measuredWith.empty())
    members.emplace_back("measured_with", measuredWithJson(scene.measuredWith, frame));
  const JsonLayoutValue root = jsonObject(std::move(members), /*oneItemPerLine=*/true);
  return layoutJson(root);
}

Scene sceneAsWritten(const Scene& scene, const std::filesystem::path& file) {
  return parseSceneFile(sceneFileJson(rebasedFor(scene, absoluteNormal(file))), file);
}

void writeSceneFile(const Scene& scene, const std::filesystem::path& file) {
  const std::string bytes = sceneFileJson(rebasedFor(scene, absoluteNormal(file)));
  // Never write a file we would refuse to read: this throws the reader's message, naming
  // `file` and the JSON path, before anything touches the disk.
  parseSceneFile(bytes, file);
  writeFileAtomically(file, bytes);
}

}  // namespace probeproxy
