#include "core/errors/input_error.h"
#include "core/scene/file_frame.h"
#include "geometry/export/runtime_export.h"
#include "geometry/scene/json_document.h"
#include "geometry/scene/json_values.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <memory>
#include <system_error>

namespace probeproxy {

namespace {

using Json = nlohmann::json;

// Each function checks one value and throws JsonProblem("<path>: ...") for the first thing
// wrong; parseRuntimeExport turns that into an InputError naming the file. Members this
// reader does not know are ignored: a runtime loader must accept additions of later versions.

// A value and where it is, so that every check can name it.
struct At {
  const Json& value;
  std::string path;

  At member(const char* name) const {
    if (!value.is_object()) failJsonExpected(path, "an object", value);
    const auto found = value.find(name);
    if (found == value.end()) failJson(path, std::string("expected member \"") + name + "\"");
    return {*found, jsonMemberPath(path, name)};
  }
  bool has(const char* name) const { return value.is_object() && value.contains(name); }
  At operator[](std::size_t i) const { return {value[i], jsonIndexPath(path, i)}; }
};

// The kit's checks (geometry/scene/json_values.h), at a value and its path.
double finiteNumber(const At& at) { return probeproxy::finiteNumber(at.value, at.path); }
double positiveNumber(const At& at) { return probeproxy::positiveNumber(at.value, at.path); }
double nonNegativeNumber(const At& at) { return probeproxy::nonNegativeNumber(at.value, at.path); }
glm::dvec3 vec3(const At& at) { return finiteVec3(at.value, at.path); }
glm::dvec3 positiveVec3(const At& at) { return probeproxy::positiveVec3(at.value, at.path); }
glm::dquat unitQuaternionWxyz(const At& at) {
  return probeproxy::unitQuaternionWxyz(at.value, at.path);
}
glm::dquat quaternionXyzw(const At& at) { return unitQuaternionXyzw(at.value, at.path); }

double numberOrNull(const At& at) {  // null: not measured
  if (at.value.is_null()) return std::nan("");
  return finiteNumber(at);
}

bool boolean(const At& at) {
  if (!at.value.is_boolean()) failJsonExpected(at.path, "true or false", at.value);
  return at.value.get<bool>();
}

std::string string(const At& at) {
  if (!at.value.is_string()) failJsonExpected(at.path, "a string", at.value);
  return at.value.get<std::string>();
}

std::size_t count(const At& at) {
  if (!at.value.is_number_unsigned()) failJsonExpected(at.path, "a non-negative integer", at.value);
  return at.value.get<std::size_t>();
}

// Unity's importance, an int.
int importance(const At& at) {
  const bool fits = at.value.is_number_unsigned()
                        ? at.value.get<std::uint64_t>() <= std::numeric_limits<int>::max()
                        : at.value.is_number_integer() &&
                              at.value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                              at.value.get<std::int64_t>() <= std::numeric_limits<int>::max();
  if (!fits) failJsonExpected(at.path, "an integer (a 32-bit int)", at.value);
  return at.value.get<int>();
}

const Json& array(const At& at) {
  if (!at.value.is_array()) failJsonExpected(at.path, "an array", at.value);
  return at.value;
}

template <std::size_t N>
std::array<double, N> finiteNumbers(const At& at) {
  if (!at.value.is_array() || at.value.size() != N) {
    failJsonExpected(at.path, "an array of " + std::to_string(N) + " finite numbers", at.value);
  }
  std::array<double, N> numbers{};
  for (std::size_t i = 0; i < N; ++i) numbers[i] = finiteNumber(at[i]);
  return numbers;
}

std::string oneOf(const At& at, std::initializer_list<std::string_view> options) {
  if (at.value.is_string()) {
    const std::string& text = at.value.get_ref<const std::string&>();
    for (std::string_view option : options) {
      if (text == option) return text;
    }
  }
  std::string expected = "one of";
  for (std::string_view option : options) {
    expected += (option == *options.begin() ? " \"" : ", \"") + std::string(option) + "\"";
  }
  failJsonExpected(at.path, expected, at.value);
}

// ------------------------------------------------------------------------------------------

class Reader {
 public:
  explicit Reader(const FileFrame& frame) : frame_(frame) {}

  glm::dvec3 point(const At& at) const {
    return checkedFinite(at, worldPointFromFile(frame_, vec3(at)));
  }
  glm::dvec3 halfExtents(const At& at) const {
    return checkedFinite(at, worldHalfExtentsFromFile(frame_, positiveVec3(at)));
  }
  double length(const At& at) const {
    const double meters = worldLengthFromFile(frame_, positiveNumber(at));
    if (!std::isfinite(meters))
      failJsonExpected(at.path, "a number that stays finite in metres", at.value);
    return meters;
  }
  double perLength(const At& at) const {  // per file unit -> per metre
    return finiteNumber(at) / frame_.metersPerUnit;
  }
  glm::dquat rotation(const At& at) const {
    return worldRotationFromFile(frame_, unitQuaternionWxyz(at));
  }

  BoxShape box(const At& at) const {
    return {point(at.member("center")), halfExtents(at.member("half_extents")),
            rotation(at.member("rotation"))};
  }

  SphereShape sphere(const At& at) const {
    return {point(at.member("center")), halfExtents(at.member("radii")),
            rotation(at.member("rotation"))};
  }

  ProxyPlane plane(const At& at) const {
    const auto c = finiteNumbers<4>(at);
    const double length = lengthOf(std::array<double, 3>{c[0], c[1], c[2]});
    if (!(std::abs(length - 1.0) <= kUnitLengthTolerance)) {
      failJsonExpected(at.path, "[nx, ny, nz, d] with a unit normal (length within 1e-3 of 1)",
                       at.value);
    }
    // Scaled as a whole, so the plane stays where it was written.
    const double scale = isUnitToRounding(length) ? 1.0 : length;
    const glm::dvec3 n = glm::dvec3(c[0], c[1], c[2]) / scale;
    return {worldDirectionFromFile(frame_, n), worldLengthFromFile(frame_, c[3] / scale)};
  }

  glm::dmat4 worldToUnit(const At& at) const {
    if (!at.value.is_array() || at.value.size() != 4) {
      failJsonExpected(at.path, "4 rows of 4 finite numbers", at.value);
    }
    glm::dmat4 fileToUnit(0.0);
    for (std::size_t r = 0; r < 4; ++r) {
      const auto row = finiteNumbers<4>(at[r]);
      for (int c = 0; c < 4; ++c)
        fileToUnit[c][static_cast<int>(r)] = row[static_cast<std::size_t>(c)];
    }
    return worldToUnitFromFile(frame_, fileToUnit);
  }

  InfluenceVolume influence(const At& at) const {
    const std::string kind = oneOf(at.member("kind"), {"box", "sphere"});
    if (kind == "box") {
      BoxInfluence box;
      box.centerMeters = point(at.member("center"));
      box.halfExtentsMeters = halfExtents(at.member("half_extents"));
      box.worldFromBox = rotation(at.member("rotation"));
      box.innerHalfExtentsMeters = halfExtents(at.member("inner_half_extents"));
      return box;
    }
    SphereInfluence sphere;
    sphere.centerMeters = point(at.member("center"));
    sphere.radiusMeters = length(at.member("radius"));
    sphere.innerRadiusMeters = length(at.member("inner_radius"));
    return sphere;
  }

  ConvexProxy convex(const At& probe) const {
    ConvexProxy convex;
    const At planes = probe.member("planes");
    for (std::size_t i = 0; i < array(planes).size(); ++i)
      convex.planes.push_back(plane(planes[i]));
    const At vertices = probe.member("vertices");
    for (std::size_t i = 0; i < array(vertices).size(); ++i) {
      convex.verticesMeters.push_back(point(vertices[i]));
    }
    const At triangles = probe.member("triangles");
    for (std::size_t i = 0; i < array(triangles).size(); ++i) {
      const At t = triangles[i];
      const bool ok = t.value.is_array() && t.value.size() == 3 &&
                      t.value[0].is_number_unsigned() && t.value[1].is_number_unsigned() &&
                      t.value[2].is_number_unsigned();
      if (!ok) failJsonExpected(t.path, "3 vertex indices", t.value);
      glm::uvec3 tri;
      for (int k = 0; k < 3; ++k) {
        const auto index = t.value[static_cast<std::size_t>(k)].get<std::uint64_t>();
        if (index >= convex.verticesMeters.size()) {
          failJsonExpected(t.path,
                           "vertex indices below " + std::to_string(convex.verticesMeters.size()),
                           t.value);
        }
        tri[k] = static_cast<unsigned>(index);
      }
      convex.triangles.push_back(tri);
    }
    return convex;
  }

 private:
  static glm::dvec3 checkedFinite(const At& at, glm::dvec3 meters) {
    if (!std::isfinite(meters.x) || !std::isfinite(meters.y) || !std::isfinite(meters.z)) {
      failJsonExpected(at.path, "numbers that stay finite in metres", at.value);
    }
    return meters;
  }

  FileFrame frame_;
};

ErrorFigures errorFigures(const At& at) {
  ErrorFigures e;
  e.medianDeg = numberOrNull(at.member("median_deg"));
  e.p95Deg = numberOrNull(at.member("p95_deg"));
  e.maxDeg = numberOrNull(at.member("max_deg"));
  e.missRate = numberOrNull(at.member("miss_rate"));
  e.occludedRate = numberOrNull(at.member("occluded_rate"));
  e.samples = count(at.member("samples"));
  return e;
}

EngineSource engineSource(const At& at) {
  return {string(at.member("candidate")), errorFigures(at.member("error")),
          boolean(at.member("kept_proxy"))};
}

template <class T, class Read>
std::optional<T> optionalEngine(const At& engines, const char* name, Read read) {
  const At at = engines.member(name);
  if (at.value.is_null()) return std::nullopt;
  if (!at.value.is_object()) failJsonExpected(at.path, "an object or null", at.value);
  T engine = read(at);
  engine.source = engineSource(at);
  return engine;
}

RuntimeEngines engines(const At& at) {
  if (!at.value.is_object()) failJsonExpected(at.path, "an object", at.value);
  RuntimeEngines e;
  e.unity = optionalEngine<UnityReflectionProbe>(at, "unity_reflection_probe", [](const At& u) {
    UnityReflectionProbe p;
    p.position = vec3(u.member("position"));
    p.center = vec3(u.member("center"));
    p.size = vec3(u.member("size"));
    // Exports before blend_distance was written leave Unity its default.
    if (u.has("blend_distance")) p.blendDistance = positiveNumber(u.member("blend_distance"));
    p.boxProjection = boolean(u.member("box_projection"));
    // Exports before importance was written leave Unity's default.
    if (u.has("importance")) p.importance = importance(u.member("importance"));
    return p;
  });
  // Entries later exports added: absent reads as none.
  if (at.has("unity_hdrp_reflection_probe")) {
    e.unityHdrp = optionalEngine<UnityHdrpReflectionProbe>(
        at, "unity_hdrp_reflection_probe", [](const At& u) {
          UnityHdrpReflectionProbe p;
          p.position = vec3(u.member("position"));
          p.rotation = quaternionXyzw(u.member("rotation_xyzw"));
          p.sphere = oneOf(u.member("influence_shape"), {"box", "sphere"}) == "sphere";
          if (p.sphere) {
            p.sphereRadius = positiveNumber(u.member("sphere_radius"));
            p.blendDistancePositive = p.blendDistanceNegative =
                glm::dvec3(finiteNumber(u.member("sphere_blend_distance")));
          } else {
            p.boxSize = positiveVec3(u.member("box_size"));
            p.blendDistancePositive = vec3(u.member("box_blend_distance_positive"));
            p.blendDistanceNegative = vec3(u.member("box_blend_distance_negative"));
          }
          p.capturePosition = vec3(u.member("capture_position"));
          p.proxyPosition = vec3(u.member("proxy_position"));
          p.proxyRotation = quaternionXyzw(u.member("proxy_rotation_xyzw"));
          p.proxySize = positiveVec3(u.member("proxy_size"));
          return p;
        });
  }
  e.unrealBox = optionalEngine<UnrealBoxReflectionCapture>(
      at, "unreal_box_reflection_capture", [](const At& u) {
        UnrealBoxReflectionCapture p;
        p.location = vec3(u.member("location"));
        p.rotation = quaternionXyzw(u.member("rotation_xyzw"));
        p.scale3D = vec3(u.member("scale_3d"));
        p.captureOffset = vec3(u.member("capture_offset"));
        p.boxTransitionDistance = finiteNumber(u.member("box_transition_distance"));
        return p;
      });
  e.unrealSphere = optionalEngine<UnrealSphereReflectionCapture>(
      at, "unreal_sphere_reflection_capture", [](const At& u) {
        UnrealSphereReflectionCapture p;
        p.location = vec3(u.member("location"));
        p.influenceRadius = finiteNumber(u.member("influence_radius"));
        p.captureOffset = vec3(u.member("capture_offset"));
        return p;
      });
  const auto godot = [](const At& g) {
    GodotReflectionProbe p;
    p.origin = vec3(g.member("origin"));
    p.rotation = quaternionXyzw(g.member("rotation_xyzw"));
    p.size = vec3(g.member("size"));
    p.originOffset = vec3(g.member("origin_offset"));
    p.blendDistance = finiteNumber(g.member("blend_distance"));
    // Exports before max_distance was written leave Godot its default, 0.
    if (g.has("max_distance")) p.maxDistance = nonNegativeNumber(g.member("max_distance"));
    p.boxProjection = boolean(g.member("box_projection"));
    p.exact = boolean(g.member("exact"));
    return p;
  };
  e.godot = optionalEngine<GodotReflectionProbe>(at, "godot_reflection_probe", godot);
  // Earlier exports had one entry for Godot 3 and 4.
  e.godot4 = at.has("godot4_reflection_probe")
                 ? optionalEngine<GodotReflectionProbe>(at, "godot4_reflection_probe", godot)
                 : e.godot;
  e.bevy = optionalEngine<BevyLightProbe>(at, "bevy_light_probe", [](const At& b) {
    BevyLightProbe p;
    p.translation = vec3(b.member("translation"));
    p.rotation = quaternionXyzw(b.member("rotation_xyzw"));
    p.scale = vec3(b.member("scale"));
    p.falloff = vec3(b.member("falloff"));
    oneOf(b.member("parallax_correction"), {"auto"});
    p.captureAtCentre = boolean(b.member("capture_at_centre"));
    p.exact = boolean(b.member("exact"));
    return p;
  });
  if (at.has("eevee_reflection_cubemap")) {
    e.eevee =
        optionalEngine<EeveeReflectionCubemap>(at, "eevee_reflection_cubemap", [](const At& b) {
          EeveeReflectionCubemap p;
          p.location = vec3(b.member("location"));
          p.rotation = quaternionXyzw(b.member("rotation_xyzw"));
          p.scale = positiveVec3(b.member("scale"));
          p.sphere = oneOf(b.member("influence_type"), {"BOX", "ELIPSOID"}) == "ELIPSOID";
          oneOf(b.member("parallax_type"), {"BOX"});
          if (positiveNumber(b.member("influence_distance")) != 1.0)
            failJson(b.member("influence_distance").path,
                     "expected 1 (Object.scale holds the size)");
          p.falloff = positiveNumber(b.member("falloff"));
          p.parallaxDistance = positiveNumber(b.member("parallax_distance"));
          return p;
        });
  }
  return e;
}

RuntimeProbe probe(const At& at, const Reader& reader) {
  if (!at.value.is_object()) failJsonExpected(at.path, "an object", at.value);
  RuntimeProbe p;
  p.name = string(at.member("name"));
  if (p.name.empty())
    failJsonExpected(jsonMemberPath(at.path, "name"), "a non-empty string", at.value["name"]);
  p.captureMeters = reader.point(at.member("capture"));
  p.method = *methodFromName(
      oneOf(at.member("kind"), {"infinite", "cheap_k", "sphere", "aabb", "obb", "convex"}));
  p.candidate = string(at.member("candidate"));
  if (p.method == Method::CheapK) {
    p.kPerMeter = reader.perLength(at.member("k"));
  }
  if (p.method == Method::Aabb || p.method == Method::Obb) p.box = reader.box(at.member("box"));
  if (p.method == Method::Sphere) p.sphere = reader.sphere(at.member("sphere"));
  if (p.box || p.sphere) p.worldToUnit = reader.worldToUnit(at.member("world_to_unit"));
  p.planesCount = static_cast<int>(count(at.member("planes_count")));
  p.convex = reader.convex(at);
  p.meshIsDisplayOnly = boolean(at.member("mesh_is_display_only"));
  p.influence = reader.influence(at.member("influence"));
  const At enlighten = at.member("blend").member("enlighten");
  p.enlighten.epsilon = finiteNumber(enlighten.member("epsilon"));
  p.enlighten.box = reader.box(enlighten.member("box"));
  p.error = errorFigures(at.member("error"));
  p.engines = engines(at.member("engines"));
  return p;
}

RuntimeExport runtimeFromDocument(const Json& root) {
  const At doc{root, "$"};
  if (!root.is_object()) failJsonExpected("$", "an object", root);
  const At version = doc.member(kRuntimeExportFormatId);
  if (!version.value.is_number() || version.value.get<double>() != kRuntimeExportVersion) {
    failJsonExpected(version.path, std::to_string(kRuntimeExportVersion), version.value);
  }
  RuntimeExport runtime;
  runtime.fileUp = oneOf(doc.member("up"), {"Y", "Z"}) == "Y" ? UpAxis::Y : UpAxis::Z;
  runtime.metersPerUnit = positiveNumber(doc.member("meters_per_unit"));
  const Reader reader(FileFrame{runtime.fileUp, runtime.metersPerUnit});
  const At probes = doc.member("probes");
  for (std::size_t i = 0; i < array(probes).size(); ++i) {
    runtime.probes.push_back(probe(probes[i], reader));
  }
  return runtime;
}

}  // namespace

RuntimeExport parseRuntimeExport(std::string_view bytes, const std::filesystem::path& file) {
  try {
    return runtimeFromDocument(parseJsonDocument(bytes));
  } catch (const JsonProblem& problem) {
    throw InputError(file, problem.what());
  }
}

RuntimeExport readRuntimeExport(const std::filesystem::path& proxiesJson) {
  return parseRuntimeExport(readJsonFile(proxiesJson), proxiesJson);
}

}  // namespace probeproxy
