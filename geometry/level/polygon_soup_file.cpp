#include "geometry/level/polygon_soup_file.h"

#include "core/errors/input_error.h"
#include "core/scene/scene_limits.h"
#include "geometry/level/off_file.h"
#include "geometry/level/ply_claims.h"

#include <CGAL/IO/PLY.h>
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

// CGAL's PLY reader sizes each face from the count before its list; ply_claims.h has checked
// every count against the bytes left, and this polygon also refuses one past the triangle
// limit (no face may fan into more triangles than the whole level may hold).
struct CornerClaim {
  std::size_t size;
};
struct CappedPolygon : std::vector<std::size_t> {
  void resize(std::size_t size) {
    if (size > inputLimits().maxTriangles + 2) throw CornerClaim{size};
    std::vector<std::size_t>::resize(size);
  }
};

// A PLY through CGAL, once ply_claims.h has checked what it claims.
PolygonSoup readPlyFile(const std::filesystem::path& file) {
  const std::string claim = plyClaimProblem(file);
  if (!claim.empty()) throw InputError(file, "malformed mesh: " + claim);
  std::vector<Point> points;
  std::vector<CappedPolygon> faces;
  bool read = false;
  try {
    read = CGAL::IO::read_PLY(file.string(), points, faces, CGAL::parameters::verbose(false));
  } catch (const CornerClaim& corners) {
    throw InputError(file, "the file claims " + std::to_string(corners.size) +
                               " corners in a face, over the limit of " +
                               std::to_string(inputLimits().maxTriangles) +
                               " triangles (raise it with --max-triangles)");
  }
  if (!read) {
    const std::string nonFinite = nonFiniteToken(file);
    if (!nonFinite.empty()) {
      throw InputError(file, "mesh '" + file.stem().string() + "' has a non-finite coordinate (" +
                                 nonFinite + ")");
    }
    throw InputError(file, "malformed mesh: not a complete ply file (header, counts or data)");
  }
  PolygonSoup soup;
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  for (const CappedPolygon& face : faces) {
    soup.corners.insert(soup.corners.end(), face.begin(), face.end());
    soup.faceEnds.push_back(soup.corners.size());
  }
  return soup;
}

}  // namespace

bool isPolygonSoupFile(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  return ext == ".off" || ext == ".ply";
}

LevelMesh readPolygonSoupFile(const std::filesystem::path& file, UpAxis fileUp,
                              double metersPerUnit) {
  const PolygonSoup soup = lowerExtension(file) == ".off" ? readOffFile(file) : readPlyFile(file);
  LevelMesh level;
  LevelPart part;
  part.name = file.stem().string();
  part.file = file;
  level.positionsMeters.reserve(soup.points.size());
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const glm::dvec3 v = soup.points[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
      std::ostringstream problem;
      problem << "mesh '" << part.name << "' vertex " << i << " has a non-finite coordinate ("
              << v.x << ", " << v.y << ", " << v.z << ")";
      throw InputError(file, problem.str());
    }
    const glm::dvec3 inFile = v * metersPerUnit;
    level.positionsMeters.emplace_back(fileUp == UpAxis::Y ? zUpFromYUp(inFile) : inFile);
  }
  // The fans' triangles counted before any is made: the limit names the level's whole count.
  std::size_t triangles = 0, begin = 0;
  for (const std::size_t end : soup.faceEnds) {
    triangles += end - begin > 2 ? end - begin - 2 : 0;
    begin = end;
  }
  if (triangles > inputLimits().maxTriangles)
    throw InputError(file, triangleLimitProblem(triangles));
  level.triangles.reserve(triangles);
  begin = 0;
  for (std::size_t f = 0; f < soup.faceEnds.size(); begin = soup.faceEnds[f++]) {
    const std::size_t end = soup.faceEnds[f];
    for (std::size_t k = begin; k < end; ++k) {
      // A negative index in a PLY reads as a huge unsigned one: both are out of range.
      if (soup.corners[k] >= soup.points.size()) {
        const auto asSigned = static_cast<long long>(soup.corners[k]);
        throw InputError(file, "mesh '" + part.name + "' face " + std::to_string(f) +
                                   " refers to vertex " + std::to_string(asSigned) + " of " +
                                   std::to_string(soup.points.size()));
      }
    }
    // Points and lines carry no surface; polygons become fans, as level faces are convex.
    for (std::size_t k = begin + 2; k < end; ++k) {
      level.triangles.emplace_back(soup.corners[begin], soup.corners[k - 1], soup.corners[k]);
    }
  }
  part.triangleCount = static_cast<std::uint32_t>(level.triangles.size());
  if (part.triangleCount > 0) level.parts.push_back(std::move(part));
  if (level.triangles.empty()) throw InputError(file, "mesh has no triangles");
  return level;
}

}  // namespace probeproxy
