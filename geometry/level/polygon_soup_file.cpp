#include "geometry/level/polygon_soup_file.h"

#include "core/errors/input_error.h"
#include "core/scene/scene_limits.h"
#include "geometry/level/ply_claims.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace probeproxy {

namespace {

using Point = CGAL::Simple_cartesian<double>::Point_3;

std::string lowerExtension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// CGAL says only that an OFF did not read; the commonest reason a person can fix is a face with
// a negative index (some exporters write -1 for "none"). Name that face, or say nothing.
std::string offFaceProblem(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string magic;
  long long vertices = 0, faces = 0, edges = 0;
  if (!(in >> magic >> vertices >> faces >> edges) || magic != "OFF" || vertices < 0 || faces < 0)
    return {};
  double coordinate = 0.0;
  for (long long i = 0; i < 3 * vertices; ++i)
    if (!(in >> coordinate)) return {};
  for (long long f = 0; f < faces; ++f) {
    long long count = 0, index = 0;
    if (!(in >> count) || count < 0) return {};
    for (long long k = 0; k < count; ++k) {
      if (!(in >> index)) return {};
      if (index < 0 || index >= vertices)
        return "face " + std::to_string(f) + " refers to vertex " + std::to_string(index) + " of " +
               std::to_string(vertices);
    }
  }
  return {};
}

// A text mesh that spells a coordinate "inf" or "nan" does not read as numbers at all; say
// what it holds rather than that it is incomplete.
std::string nonFiniteToken(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string token;
  while (in >> token) {
    std::string lower = token;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (!lower.empty() && (lower[0] == '+' || lower[0] == '-')) lower.erase(0, 1);
    if (lower == "inf" || lower == "infinity" || lower == "nan") return token;
  }
  return {};
}

// CGAL's OFF reader sizes its ranges from the header's counts, and each face from its own
// count, before it reads the data that would fill them: a 60-byte file claiming a face of
// 2^31 corners took 17 GB. These ranges refuse, while CGAL reads, a size that the file or the
// triangle limit cannot back: no more vertices or faces or corners than half the file's bytes
// (each takes a digit and a separator at the least), no more faces than the triangle limit,
// no more vertices than three a triangle.
struct SizeClaim {
  std::size_t size;
  const char* what;
};
struct SoupCaps {
  std::size_t points = 0, polygons = 0, corners = 0;
};
thread_local SoupCaps soupCaps;

template <class T, std::size_t SoupCaps::*cap>
struct CappedRange : std::vector<T> {
  void resize(std::size_t size) {
    if (size > soupCaps.*cap) {
      throw SizeClaim{size, cap == &SoupCaps::points     ? "vertices"
                            : cap == &SoupCaps::polygons ? "faces"
                                                         : "corners in a face"};
    }
    std::vector<T>::resize(size);
  }
};
using Polygon = CappedRange<std::size_t, &SoupCaps::corners>;

}  // namespace

bool isPolygonSoupFile(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  return ext == ".off" || ext == ".ply";
}

LevelMesh readPolygonSoupFile(const std::filesystem::path& file, UpAxis fileUp,
                              double metersPerUnit) {
  if (lowerExtension(file) == ".ply") {
    const std::string claim = plyClaimProblem(file);
    if (!claim.empty()) throw InputError(file, "malformed mesh: " + claim);
  }
  std::error_code ec;
  const std::size_t halfTheBytes = std::filesystem::file_size(file, ec) / 2;
  const std::size_t maxTriangles = inputLimits().maxTriangles;
  soupCaps = {std::min(halfTheBytes, 3 * maxTriangles), std::min(halfTheBytes, maxTriangles),
              std::min(halfTheBytes, maxTriangles + 2)};
  CappedRange<Point, &SoupCaps::points> points;
  CappedRange<Polygon, &SoupCaps::polygons> faces;
  bool read = false;
  try {
    read = CGAL::IO::read_polygon_soup(file.string(), points, faces, CGAL::parameters::verbose(false));
  } catch (const SizeClaim& claim) {
    const std::string claimed = "the file claims " + std::to_string(claim.size) + " " + claim.what;
    if (claim.size > halfTheBytes) {
      throw InputError(file, "malformed mesh: " + claimed + ", more than its " +
                                 std::to_string(std::filesystem::file_size(file, ec)) + " bytes can hold");
    }
    throw InputError(file, claimed + ", over the limit of " + std::to_string(maxTriangles) +
                               " triangles (raise it with --max-triangles)");
  }
  if (!read) {
    const std::string face = lowerExtension(file) == ".off" ? offFaceProblem(file) : "";
    if (!face.empty()) throw InputError(file, "malformed mesh: " + face);
    const std::string nonFinite = nonFiniteToken(file);
    if (!nonFinite.empty()) {
      throw InputError(file, "mesh '" + file.stem().string() + "' has a non-finite coordinate (" +
                                 nonFinite + ")");
    }
    throw InputError(file, "malformed mesh: not a complete " + lowerExtension(file).substr(1) +
                               " file (header, counts or data)");
  }

  LevelMesh level;
  LevelPart part;
  part.name = file.stem().string();
  part.file = file;
  level.positionsMeters.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3 v(points[i].x(), points[i].y(), points[i].z());
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      std::ostringstream problem;
      problem << "mesh '" << part.name << "' vertex " << i << " has a non-finite coordinate ("
              << v.x << ", " << v.y << ", " << v.z << ")";
      throw InputError(file, problem.str());
    }
    const glm::dvec3 inFile = v * metersPerUnit;
    level.positionsMeters.emplace_back(fileUp == UpAxis::Y ? zUpFromYUp(inFile) : inFile);
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const std::size_t index : faces[f]) {
      // A negative index in the file reads as a huge unsigned one: both are out of range.
      if (index >= points.size()) {
        const auto asSigned = static_cast<long long>(index);
        throw InputError(file, "mesh '" + part.name + "' face " + std::to_string(f) +
                                   " refers to vertex " + std::to_string(asSigned) + " of " +
                                   std::to_string(points.size()));
      }
    }
    // Points and lines carry no surface; polygons become fans, as level faces are convex.
    for (std::size_t k = 2; k < faces[f].size(); ++k) {
      level.triangles.emplace_back(faces[f][0], faces[f][k - 1], faces[f][k]);
    }
  }
  part.triangleCount = static_cast<std::uint32_t>(level.triangles.size());
  if (part.triangleCount > 0) level.parts.push_back(std::move(part));
  if (level.triangles.empty()) throw InputError(file, "mesh has no triangles");
  return level;
}

}  // namespace probeproxy
