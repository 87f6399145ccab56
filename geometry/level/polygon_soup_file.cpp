#include "geometry/level/polygon_soup_file.h"

#include "core/errors/input_error.h"

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

}  // namespace

bool isPolygonSoupFile(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  return ext == ".off" || ext == ".ply";
}

LevelMesh readPolygonSoupFile(const std::filesystem::path& file, UpAxis fileUp,
                              double metersPerUnit) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  if (!CGAL::IO::read_polygon_soup(file.string(), points, faces,
                                   CGAL::parameters::verbose(false))) {
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
