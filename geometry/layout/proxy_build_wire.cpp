#include "geometry/layout/proxy_build_wire.h"

#include "geometry/layout/wire_bytes.h"

#include <cstdint>
#include <type_traits>
#include <variant>

namespace probeproxy {

namespace {

constexpr std::string_view kTaskMagic = "PPBT";
constexpr std::string_view kBuildMagic = "PPBB";
constexpr std::uint32_t kVersion = 2;
constexpr const char* kWhat = "proxy build wire";

void putQuat(std::string& out, const glm::dquat& q) {
  for (double part : {q.w, q.x, q.y, q.z}) wire::put(out, part);
}

glm::dquat getQuat(wire::Reader& in) {
  const double w = in.get<double>(), x = in.get<double>(), y = in.get<double>(),
               z = in.get<double>();
  return glm::dquat(w, x, y, z);
}

void putInfluence(std::string& out, const InfluenceVolume& influence) {
  wire::put<std::uint8_t>(out, static_cast<std::uint8_t>(influence.index()));
  if (const auto* box = std::get_if<BoxInfluence>(&influence)) {
    wire::put(out, box->centerMeters);
    wire::put(out, box->halfExtentsMeters);
    putQuat(out, box->worldFromBox);
    wire::put(out, box->innerHalfExtentsMeters);
  } else {
    const auto& sphere = std::get<SphereInfluence>(influence);
    wire::put(out, sphere.centerMeters);
    wire::put(out, sphere.radiusMeters);
    wire::put(out, sphere.innerRadiusMeters);
  }
}

InfluenceVolume getInfluence(wire::Reader& in) {
  switch (in.get<std::uint8_t>()) {
    case 0: {
      BoxInfluence box;
      box.centerMeters = in.get<glm::dvec3>();
      box.halfExtentsMeters = in.get<glm::dvec3>();
      box.worldFromBox = getQuat(in);
      box.innerHalfExtentsMeters = in.get<glm::dvec3>();
      return box;
    }
    case 1: {
      SphereInfluence sphere;
      sphere.centerMeters = in.get<glm::dvec3>();
      sphere.radiusMeters = in.get<double>();
      sphere.innerRadiusMeters = in.get<double>();
      return sphere;
    }
    default:
      throw InputError(kWhat, "an influence volume of no known kind at " + std::to_string(in.at));
  }
}

void putShape(std::string& out, const ProxyShape& shape) {
  wire::put<std::uint8_t>(out, static_cast<std::uint8_t>(shape.index()));
  std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, CheapKShape>) {
          wire::put(out, s.kPerMeter);
        } else if constexpr (std::is_same_v<S, SphereShape>) {
          wire::put(out, s.centerMeters);
          wire::put(out, s.radiiMeters);
          putQuat(out, s.worldFromSphere);
        } else if constexpr (std::is_same_v<S, BoxShape>) {
          wire::put(out, s.centerMeters);
          wire::put(out, s.halfExtentsMeters);
          putQuat(out, s.worldFromBox);
        } else if constexpr (std::is_same_v<S, ConvexProxy>) {
          wire::put<std::uint64_t>(out, s.planes.size());
          for (const ProxyPlane& p : s.planes) {
            wire::put(out, p.normal);
            wire::put(out, p.offsetMeters);
          }
          wire::put<std::uint64_t>(out, s.verticesMeters.size());
          for (const glm::dvec3& v : s.verticesMeters) wire::put(out, v);
          wire::put<std::uint64_t>(out, s.triangles.size());
          for (const glm::uvec3& t : s.triangles) wire::put(out, t);
        }
      },
      shape);
}

ConvexProxy getConvex(wire::Reader& in) {
  ConvexProxy convex;
  convex.planes.resize(in.getCount(sizeof(glm::dvec3) + sizeof(double)));
  for (ProxyPlane& p : convex.planes) {
    p.normal = in.get<glm::dvec3>();
    p.offsetMeters = in.get<double>();
  }
  convex.verticesMeters.resize(in.getCount(sizeof(glm::dvec3)));
  for (glm::dvec3& v : convex.verticesMeters) v = in.get<glm::dvec3>();
  convex.triangles.resize(in.getCount(sizeof(glm::uvec3)));
  for (glm::uvec3& t : convex.triangles) {
    t = in.get<glm::uvec3>();
    for (int k = 0; k < 3; ++k)
      if (t[k] >= convex.verticesMeters.size())
        throw InputError(kWhat, "a proxy triangle names corner " + std::to_string(t[k]) + " of " +
                                    std::to_string(convex.verticesMeters.size()));
  }
  return convex;
}

ProxyShape getShape(wire::Reader& in) {
  switch (in.get<std::uint8_t>()) {
    case 0:
      return InfiniteShape{};
    case 1:
      return CheapKShape{in.get<double>()};
    case 2: {
      SphereShape s;
      s.centerMeters = in.get<glm::dvec3>();
      s.radiiMeters = in.get<glm::dvec3>();
      s.worldFromSphere = getQuat(in);
      return s;
    }
    case 3: {
      BoxShape s;
      s.centerMeters = in.get<glm::dvec3>();
      s.halfExtentsMeters = in.get<glm::dvec3>();
      s.worldFromBox = getQuat(in);
      return s;
    }
    case 4:
      return getConvex(in);
    default:
      throw InputError(kWhat, "a proxy shape of no known kind at " + std::to_string(in.at));
  }
}

void putFigures(std::string& out, const ErrorFigures& e) {
  for (double d : {e.medianDeg, e.p95Deg, e.maxDeg, e.meanCostDeg, e.p95WithMissesDeg, e.missRate,
                   e.occludedRate})
    wire::put(out, d);
  wire::put<std::uint64_t>(out, e.samples);
}

ErrorFigures getFigures(wire::Reader& in) {
  ErrorFigures e;
  for (double* d : {&e.medianDeg, &e.p95Deg, &e.maxDeg, &e.meanCostDeg, &e.p95WithMissesDeg,
                    &e.missRate, &e.occludedRate})
    *d = in.get<double>();
  e.samples = in.get<std::uint64_t>();
  return e;
}

}  // namespace

std::string packProxyBuildTask(const ProxyBuildTask& task) {
  std::string out(kTaskMagic);
  wire::put(out, kVersion);
  wire::putString(out, task.probe.name);
  wire::put(out, task.probe.captureMeters);
  putInfluence(out, task.probe.influence);
  wire::put(out, task.candidateFitMeters);
  wire::put<std::uint64_t>(out, task.blendVolumes.size());
  for (const InfluenceVolume& v : task.blendVolumes) putInfluence(out, v);
  wire::put<std::int64_t>(out, task.blendIndex);
  return out;
}

ProxyBuildTask unpackProxyBuildTask(std::string_view bytes) {
  wire::Reader in{kWhat, bytes};
  in.expectHeader(kTaskMagic, "a proxy build task", kVersion);
  ProxyBuildTask task;
  task.probe.name = in.getString();
  task.probe.captureMeters = in.get<glm::dvec3>();
  task.probe.influence = getInfluence(in);
  task.candidateFitMeters = in.get<double>();
  // The smallest volume: its kind and a sphere's centre and two radii.
  task.blendVolumes.resize(in.getCount(1 + 5 * sizeof(double)));
  for (InfluenceVolume& v : task.blendVolumes) v = getInfluence(in);
  const auto index = in.get<std::int64_t>();
  if (!task.blendVolumes.empty() && (index < 0 || index >= std::ssize(task.blendVolumes)))
    throw InputError(kWhat, "the probe's volume is " + std::to_string(index) + " of " +
                                std::to_string(task.blendVolumes.size()));
  task.blendIndex = static_cast<int>(index);
  in.expectEnd("the task");
  return task;
}

std::string packProxyBuild(const ProbeProxyBuild& build) {
  std::string out(kBuildMagic);
  wire::put(out, kVersion);
  wire::putString(out, build.probe);
  wire::put<std::uint64_t>(out, build.kept);
  wire::put<std::uint64_t>(out, build.candidates.size());
  for (const ProxyCandidate& c : build.candidates) {
    wire::put<std::uint8_t>(out, static_cast<std::uint8_t>(c.origin));
    putShape(out, c.shape);
    putFigures(out, c.error);
    putFigures(out, c.errorAllSurfaces);
    wire::put(out, c.buildMs);
  }
  for (double ms : {build.buildMs, build.depthMs, build.samplingMs, build.hullMs, build.simplifyMs,
                    build.fitMs, build.evaluateMs})
    wire::put(out, ms);
  wire::put<std::uint64_t>(out, build.findings.size());
  for (const std::string& finding : build.findings) wire::putString(out, finding);
  return out;
}

ProbeProxyBuild unpackProxyBuild(std::string_view bytes) {
  wire::Reader in{kWhat, bytes};
  in.expectHeader(kBuildMagic, "a proxy build", kVersion);
  ProbeProxyBuild build;
  build.probe = in.getString();
  build.kept = in.get<std::uint64_t>();
  // The smallest candidate: origin, an infinite shape, two figures, its time.
  build.candidates.resize(in.getCount(2 + 2 * 8 * sizeof(double) + sizeof(double)));
  for (ProxyCandidate& c : build.candidates) {
    const auto origin = in.get<std::uint8_t>();
    if (origin > static_cast<std::uint8_t>(CandidateOrigin::Simplified))
      throw InputError(kWhat, "a candidate of no known origin (" + std::to_string(origin) + ")");
    c.origin = static_cast<CandidateOrigin>(origin);
    c.shape = getShape(in);
    c.error = getFigures(in);
    c.errorAllSurfaces = getFigures(in);
    c.buildMs = in.get<double>();
  }
  if (build.kept >= build.candidates.size())
    throw InputError(kWhat, "kept candidate " + std::to_string(build.kept) + " of " +
                                std::to_string(build.candidates.size()));
  for (double* ms : {&build.buildMs, &build.depthMs, &build.samplingMs, &build.hullMs,
                     &build.simplifyMs, &build.fitMs, &build.evaluateMs})
    *ms = in.get<double>();
  build.findings.resize(in.getCount(sizeof(std::uint64_t)));
  for (std::string& finding : build.findings) finding = in.getString();
  in.expectEnd("the build");
  return build;
}

}  // namespace probeproxy
