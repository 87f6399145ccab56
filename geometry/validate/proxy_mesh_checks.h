#pragma once
// Checks for a proxy mesh that an artist authored (or that the builder produced): is it one
// closed, consistently wound, outward-facing, convex surface around the capture point? Every
// finding names the rule, the measured amount, the limit, where it is (vertex and face indices
// of the input, coordinates in metres) and how to fix it. A valid proxy gives no findings.
//
// Tolerances are relative to the mesh size (its bounding-box diagonal), so a 10 cm box and a
// room 10 km from the origin are judged alike.

#include "core/proxy/convex_proxy.h"
#include "geometry/level/level_mesh.h"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace probeproxy {

struct ProxyMeshFinding {
  std::string rule;      // stable id, see the rule list below
  std::string severity;  // "error" or "warning"
  double value = 0.0;    // the measured amount, in the unit the rule list gives
  double limit = 0.0;    // the limit it broke
  std::string message;   // one line: what and where (input vertex/face indices, coordinates)
  std::string hint;      // one line: how to fix it
};

// clang-format off
// Rules, in the order findings are returned (value / limit); proxy_empty also ends the list
// when no triangle with an area is left:
//   rule                         severity  what                                    value / limit
//   proxy_empty                  error     no triangles, or none with an area      usable triangles / 1
//   proxy_degenerate_face        warning   zero-area faces (kept for closedness,   count / 0
//                                          skipped for angles)
//   proxy_not_manifold           error     faces that do not fit one 2-manifold    count / 0
//                                          surface (an edge already shared by two
//                                          faces, a vertex whose fan is closed);
//                                          left out of the later checks
//   proxy_not_closed             error     edges used by one face only             count / 0
//   proxy_not_oriented           error     faces wound against their neighbours    count / 0
//                                          (or a one-sided surface)
//   proxy_separate_pieces        error     several pieces sharing no edge          pieces / 1
//   proxy_flat                   error     encloses no volume                      |volume| m^3 / tolerance m^3
//   proxy_inward_faces           error     signed volume negative                  volume m^3 / 0
//   proxy_concave_edge           error     worst inward bend between two faces     degrees / tolerance degrees
//   proxy_not_convex             error     every edge bends outwards, yet the      metres / tolerance metres
//                                          surface overlaps itself: the farthest a (plane tolerance + size *
//                                          vertex lies outside a face's plane      sin(angle tolerance))
//   proxy_misses_capture         error     capture point outside or on the         signed metres outside the
//                                          boundary                                worst face plane / -tolerance
// checkConvexProxy adds:
//   proxy_bad_plane              error     a plane normal that is not unit length  length / 1
//   proxy_face_off_planes        error     triangles on none of the planes         worst metres off / tolerance
//   proxy_vertex_outside_planes  error     vertices outside a plane                worst metres outside / tolerance
// clang-format on
struct ProxyMeshCheckOptions {
  // An edge is concave when its two faces bend inwards by more than this (0 = coplanar).
  double convexToleranceDegrees = 0.5;
  // Corners closer than this times the mesh size are one vertex (exporters split vertices).
  double weldToleranceRelative = 1e-6;
  // A triangle whose height (2 * area / longest edge) is under this times the mesh size has
  // zero area: the area tolerance per metre of edge, so slivers of any length are caught.
  double degenerateHeightRelative = 1e-6;
  // How far off a plane, times the mesh size, still counts as on it: the capture point on the
  // boundary, vertices outside face planes, ConvexProxy triangles on its planes.
  double planeToleranceRelative = 1e-6;
};

// Checks one triangle mesh (indices into verticesMeters; unreferenced vertices are ignored).
// Throws std::invalid_argument for an index out of range, a non-finite coordinate of a
// referenced vertex or capture point, or a negative or non-finite option.
std::vector<ProxyMeshFinding> checkProxyMesh(const std::vector<glm::dvec3>& verticesMeters,
                                             const std::vector<glm::uvec3>& triangles,
                                             glm::dvec3 captureMeters,
                                             const ProxyMeshCheckOptions& options = {});

// The same for an authored mesh read with loadLevelMeshFile (geometry/level/load_level.h).
std::vector<ProxyMeshFinding> checkProxyMesh(const LevelMesh& mesh, glm::dvec3 captureMeters,
                                             const ProxyMeshCheckOptions& options = {});

// checkProxyMesh on the proxy's boundary, then: plane normals unit, every triangle on one of
// the planes, every vertex inside every plane (all within the plane tolerance).
std::vector<ProxyMeshFinding> checkConvexProxy(const ConvexProxy& proxy, glm::dvec3 captureMeters,
                                               const ProxyMeshCheckOptions& options = {});

}  // namespace probeproxy
