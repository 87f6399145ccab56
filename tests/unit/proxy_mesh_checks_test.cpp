#include "geometry/validate/proxy_mesh_checks.h"

#include "core/proxy/proxy_shape.h"
#include "geometry/level/load_level.h"
#include "test_files.h"

#include <glm/gtc/quaternion.hpp>

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace probeproxy {
namespace {

using ::testing::ContainsRegex;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

struct Mesh {
  std::vector<glm::dvec3> vertices;
  std::vector<glm::uvec3> triangles;
};

// A prism over a polygon wound counter-clockwise seen from +Z, from z = 0 to z = height.
// Vertex i is the polygon's corner i at the bottom, n + i the same corner at the top.
// Faces: the bottom fan from corner 0 (n - 2 faces), the top fan (n - 2), then for each
// polygon edge i -> i+1 a wall of two faces (bottom_i, bottom_i+1, top_i+1), (bottom_i,
// top_i+1, top_i). Corner 0 must see every other corner (true for convex polygons and the L).
Mesh prism(const std::vector<glm::dvec2>& polygon, double height) {
  Mesh m;
  const auto n = static_cast<unsigned>(polygon.size());
  for (const glm::dvec2& p : polygon) m.vertices.emplace_back(p.x, p.y, 0.0);
  for (const glm::dvec2& p : polygon) m.vertices.emplace_back(p.x, p.y, height);
  for (unsigned i = 1; i + 1 < n; ++i) m.triangles.emplace_back(0, i + 1, i);
  for (unsigned i = 1; i + 1 < n; ++i) m.triangles.emplace_back(n, n + i, n + i + 1);
  for (unsigned i = 0; i < n; ++i) {
    const unsigned j = (i + 1) % n;
    m.triangles.emplace_back(i, j, n + j);
    m.triangles.emplace_back(i, n + j, n + i);
  }
  return m;
}

// The unit cube [0,1]^3: bottom 0 (0,0,0) 1 (1,0,0) 2 (1,1,0) 3 (0,1,0), top 4..7 above them.
// Faces 0-1 bottom, 2-3 top, 4-5 y=0, 6-7 x=1, 8-9 y=1, 10-11 x=0.
Mesh unitCube() { return prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1.0); }

// As OBJ and glTF exporters write flat-shaded meshes: every face its own corners. Each copy is
// moved by up to `jitter` (as printing and parsing floats does), so only a tolerant weld joins
// them.
Mesh splitPerFace(const Mesh& in, double jitter) {
  Mesh out;
  for (const glm::uvec3& t : in.triangles) {
    const auto base = static_cast<unsigned>(out.vertices.size());
    for (int k = 0; k < 3; ++k) {
      // A different amount for every copy, so no two copies coincide exactly.
      const double s = jitter * static_cast<double>(out.vertices.size() + 1) /
                       static_cast<double>(3 * in.triangles.size());
      out.vertices.push_back(in.vertices[t[k]] + glm::dvec3(s, -s, s));
    }
    out.triangles.emplace_back(base, base + 1, base + 2);
  }
  return out;
}

Mesh transformed(const Mesh& in, double scale, glm::dquat rotation, glm::dvec3 offset) {
  Mesh out = in;
  for (glm::dvec3& v : out.vertices) v = offset + rotation * (scale * v);
  return out;
}

void flip(glm::uvec3& t) { std::swap(t[1], t[2]); }

std::vector<std::string> rules(const std::vector<ProxyMeshFinding>& findings) {
  std::vector<std::string> ids;
  for (const ProxyMeshFinding& f : findings) ids.push_back(f.rule);
  return ids;
}

std::vector<ProxyMeshFinding> check(const Mesh& m, glm::dvec3 capture,
                                    const ProxyMeshCheckOptions& options = {}) {
  return checkProxyMesh(m.vertices, m.triangles, capture, options);
}

const glm::dvec3 kCentre(0.5, 0.5, 0.5);

// ---- Valid meshes ---------------------------------------------------------------------------

TEST(ProxyMeshChecks, UnitCubeHasNoFindings) {
  EXPECT_THAT(rules(check(unitCube(), kCentre)), IsEmpty());
}

TEST(ProxyMeshChecks, SplitVerticesAreWelded) {
  const Mesh split = splitPerFace(unitCube(), 1e-9);
  ASSERT_EQ(split.vertices.size(), 36u);
  EXPECT_THAT(rules(check(split, kCentre)), IsEmpty());

  // Without the tolerant weld every edge is open and every triangle its own piece: the jitter
  // is what the weld must absorb.
  ProxyMeshCheckOptions exactOnly;
  exactOnly.weldToleranceRelative = 0.0;
  const std::vector<ProxyMeshFinding> unwelded = check(split, kCentre, exactOnly);
  ASSERT_THAT(rules(unwelded), ElementsAre("proxy_not_closed", "proxy_separate_pieces"));
  EXPECT_EQ(unwelded[0].value, 36.0);
  EXPECT_THAT(unwelded[0].message,
              HasSubstr("36 open edges (used by one face only) around 12 holes"));
  EXPECT_EQ(unwelded[1].value, 12.0);
}

class ProxyMeshChecksFiles : public testing::TempFolderTest {};

TEST_F(ProxyMeshChecksFiles, ObjCubeWithSplitVerticesHasNoFindings) {
  // Written as exporters do: four corners per face, quads, no shared vertices.
  const std::filesystem::path obj = write("proxy.obj", R"(# cube [0,2]^3, one quad per face
v 0 0 0
v 0 2 0
v 2 2 0
v 2 0 0
v 0 0 2
v 2 0 2
v 2 2 2
v 0 2 2
v 0 0 0
v 2 0 0
v 2 0 2
v 0 0 2
v 2 0 0
v 2 2 0
v 2 2 2
v 2 0 2
v 2 2 0
v 0 2 0
v 0 2 2
v 2 2 2
v 0 2 0
v 0 0 0
v 0 0 2
v 0 2 2
f 1 2 3 4
f 5 6 7 8
f 9 10 11 12
f 13 14 15 16
f 17 18 19 20
f 21 22 23 24
)");
  const LevelMesh mesh = loadLevelMeshFile(obj, UpAxis::Z, 1.0);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  EXPECT_THAT(rules(checkProxyMesh(mesh, {1.0, 1.0, 1.0})), IsEmpty());
  // The same file with the capture point outside proves the mesh was really checked.
  EXPECT_THAT(rules(checkProxyMesh(mesh, {3.0, 1.0, 1.0})), ElementsAre("proxy_misses_capture"));
}

// Tolerances follow the mesh size: a 4 m box 10 km from the origin, turned so no coordinate is
// round, and a 10 cm box; both split per face like an export, with jitter at their own scale.
TEST(ProxyMeshChecks, FarAwayAndSmallCubesHaveNoFindings) {
  const glm::dquat turn = glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 2, 3)));
  struct Case {
    double scale;
    glm::dvec3 offset;
  };
  for (const Case& c : {Case{4.0, {10000.0, -7000.0, 7000.0}}, Case{0.1, {0.0, 0.0, 0.0}},
                        Case{0.1, {10000.0, 0.0, 0.0}}}) {
    SCOPED_TRACE(::testing::Message() << "scale " << c.scale << " offset " << c.offset.x);
    const Mesh box = splitPerFace(transformed(unitCube(), c.scale, turn, c.offset), 1e-9 * c.scale);
    // 1 mm inside the x = 1 face (faces 6 and 7), far from the tolerance of either size.
    const glm::dvec3 inside =
        c.offset + turn * (c.scale * glm::dvec3(1.0, 0.5, 0.5) - glm::dvec3(0.001, 0.0, 0.0));
    EXPECT_THAT(rules(check(box, inside)), IsEmpty());
    const glm::dvec3 outside =
        c.offset + turn * (c.scale * glm::dvec3(1.0, 0.5, 0.5) + glm::dvec3(0.001, 0.0, 0.0));
    const std::vector<ProxyMeshFinding> missed = check(box, outside);
    ASSERT_THAT(rules(missed), ElementsAre("proxy_misses_capture"));
    EXPECT_NEAR(missed[0].value, 0.001, 1e-9);
    // Faces 6 and 7 are both on that side; rounding picks one.
    EXPECT_THAT(missed[0].message,
                ContainsRegex(" m outside the proxy, beyond the plane of face [67] "));
  }
}

// ---- Broken meshes --------------------------------------------------------------------------

TEST(ProxyMeshChecks, EmptyMesh) {
  const std::vector<ProxyMeshFinding> findings = checkProxyMesh({}, {}, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_empty"));
  EXPECT_EQ(findings[0].severity, "error");
  EXPECT_EQ(findings[0].value, 0.0);
  EXPECT_EQ(findings[0].message, "the proxy mesh has no triangles (0 vertices)");
}

TEST(ProxyMeshChecks, MissingFaceLeavesOpenEdges) {
  Mesh m = unitCube();
  m.triangles.erase(m.triangles.begin() + 2);  // (4, 5, 6): half of the top
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_not_closed"));
  EXPECT_EQ(findings[0].severity, "error");
  EXPECT_EQ(findings[0].value, 3.0);
  EXPECT_EQ(findings[0].limit, 0.0);
  EXPECT_EQ(findings[0].message,
            "the mesh is not closed: 3 open edges (used by one face only) around 1 hole; the "
            "first joins vertex 4 (0, 0, 1) and vertex 5 (1, 0, 1)");
}

TEST(ProxyMeshChecks, WholeMissingSideIsOneHoleOfFourEdges) {
  Mesh m = unitCube();
  m.triangles.erase(m.triangles.begin() + 2, m.triangles.begin() + 4);  // the whole top
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_not_closed"));
  EXPECT_EQ(findings[0].value, 4.0);
  EXPECT_THAT(findings[0].message, HasSubstr("4 open edges (used by one face only) around 1 hole"));
}

TEST(ProxyMeshChecks, FlippedFaceIsWoundAgainstItsNeighbours) {
  Mesh m = unitCube();
  flip(m.triangles[7]);
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_not_oriented"));
  EXPECT_EQ(findings[0].value, 1.0);
  EXPECT_EQ(
      findings[0].message,
      "1 face is wound against its neighbours: face 7; the first is face 7 (vertices 1, 5, 6)");
}

TEST(ProxyMeshChecks, AllFacesFlippedPointInwards) {
  Mesh m = unitCube();
  for (glm::uvec3& t : m.triangles) flip(t);
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_inward_faces"));
  EXPECT_NEAR(findings[0].value, -1.0, 1e-12);
  EXPECT_EQ(findings[0].limit, 0.0);
  EXPECT_THAT(findings[0].message, HasSubstr("faces point inwards: the signed volume is -1 m^3"));
}

TEST(ProxyMeshChecks, LShapedPrismHasConcaveEdge) {
  // The reflex corner (1, 1) is polygon corner 3: its vertical edge joins vertices 3 and 9, and
  // the walls there meet at 270 degrees inside, a 90 degree inward bend.
  const Mesh l = prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1.0);
  const std::vector<ProxyMeshFinding> findings = check(l, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_concave_edge"));
  EXPECT_NEAR(findings[0].value, 90.0, 1e-9);
  EXPECT_EQ(findings[0].limit, 0.5);
  EXPECT_EQ(
      findings[0].message,
      "1 edge bends inwards; the worst, from vertex 3 (1, 1, 0) to vertex 9 (1, 1, 1) between "
      "faces 12 and 15, bends inwards by 90 degrees");
}

TEST(ProxyMeshChecks, ShallowBendWithinToleranceIsConvex) {
  // The y = 0 wall folds inwards by 0.15 degrees at polygon corner 0 (1, 0): accepted with the
  // default tolerance of 0.5 degrees, not with 0.1.
  const double sag = std::tan(0.15 * std::numbers::pi / 180.0);
  const Mesh m = prism({{1, 0}, {2, -sag}, {2, 1}, {0, 1}, {0, 0}}, 1.0);
  EXPECT_THAT(rules(check(m, {1.0, 0.5, 0.5})), IsEmpty());
  ProxyMeshCheckOptions strict;
  strict.convexToleranceDegrees = 0.1;
  const std::vector<ProxyMeshFinding> findings = check(m, {1.0, 0.5, 0.5}, strict);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_concave_edge"));
  EXPECT_NEAR(findings[0].value, 0.15, 1e-9);
  EXPECT_EQ(findings[0].limit, 0.1);
}

TEST(ProxyMeshChecks, ZeroAreaFaceIsDegenerate) {
  // A T-junction closed with a sliver, as modelling tools leave it: face 4 (0, 1, 5) is split
  // at the midpoint 8 of its edge 0-1, and face 13 (0, 1, 8) fills the gap with no area.
  Mesh m = unitCube();
  m.vertices.emplace_back(0.5, 0.0, 0.0);
  m.triangles[4] = {0, 8, 5};
  m.triangles.emplace_back(8, 1, 5);
  m.triangles.emplace_back(0, 1, 8);
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_degenerate_face"));
  EXPECT_EQ(findings[0].severity, "warning");
  EXPECT_EQ(findings[0].value, 1.0);
  EXPECT_THAT(findings[0].message,
              HasSubstr("1 face has zero area (height under 1.73205081e-06 m): face 13; the first "
                        "is face 13 (vertices 0, 1, 8)"));
}

TEST(ProxyMeshChecks, RepeatedCornerIsDegenerate) {
  Mesh m = unitCube();
  m.triangles.emplace_back(2, 2, 3);
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_degenerate_face"));
  EXPECT_THAT(findings[0].message, HasSubstr("face 12 (vertices 2, 2, 3)"));
}

TEST(ProxyMeshChecks, ThreeFacesOnOneEdgeAreNotManifold) {
  // A fin on the cube's edge 0-1: the edge now has three faces, the fin two free edges.
  for (bool finFirst : {false, true}) {
    SCOPED_TRACE(finFirst ? "fin is face 0" : "fin is face 12");
    Mesh m = unitCube();
    m.vertices.emplace_back(0.5, -0.5, -0.5);
    const glm::uvec3 fin(0, 1, 8);
    if (finFirst) {
      m.triangles.insert(m.triangles.begin(), fin);
    } else {
      m.triangles.push_back(fin);
    }
    const std::string finName = finFirst ? "face 0" : "face 12";
    const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
    ASSERT_THAT(rules(findings), ElementsAre("proxy_not_manifold", "proxy_not_closed"));
    EXPECT_EQ(findings[0].value, 1.0);
    EXPECT_EQ(findings[0].message,
              "1 face does not fit one 2-manifold surface and is left out of the other checks: " +
                  finName + "; " + finName +
                  " (vertices 0, 1, 8): its edge from vertex 0 (0, 0, 0) to vertex 1 (1, 0, 0) is "
                  "shared by 3 faces");
    EXPECT_EQ(findings[1].value, 2.0);  // the fin's other two edges
  }
}

TEST(ProxyMeshChecks, CubesTouchingAtACornerAreNotManifold) {
  Mesh m = unitCube();
  const Mesh second = transformed(unitCube(), 1.0, glm::dquat(1, 0, 0, 0), {1.0, 1.0, 1.0});
  // Share the touching corner: the second cube's vertex 0 is the first cube's vertex 6.
  const auto base = static_cast<unsigned>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), second.vertices.begin(), second.vertices.end());
  for (glm::uvec3 t : second.triangles) m.triangles.push_back(t + glm::uvec3(base));
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings[0].rule, "proxy_not_manifold");
  EXPECT_THAT(findings[0].message,
              HasSubstr("its vertex 6 (1, 1, 1) already has a closed fan of faces"));
}

TEST(ProxyMeshChecks, SeparatePiecesAreReported) {
  Mesh m = unitCube();
  const Mesh second = transformed(unitCube(), 1.0, glm::dquat(1, 0, 0, 0), {3.0, 0.0, 0.0});
  const auto base = static_cast<unsigned>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), second.vertices.begin(), second.vertices.end());
  for (glm::uvec3 t : second.triangles) m.triangles.push_back(t + glm::uvec3(base));
  const std::vector<ProxyMeshFinding> findings = check(m, kCentre);
  ASSERT_THAT(rules(findings), ElementsAre("proxy_separate_pieces", "proxy_misses_capture"));
  EXPECT_EQ(findings[0].value, 2.0);
  EXPECT_EQ(
      findings[0].message,
      "the mesh is 2 separate pieces that share no edge; the first face of each: faces 0 and 12");
  EXPECT_EQ(findings[1].value, 2.5);  // beyond the second cube's x = 3 face
}

TEST(ProxyMeshChecks, OpenSpiralIsNotConvex) {
  // A hexagonal wall strip wound round twice, its radius shrinking by 10 cm a turn: every edge
  // bends outwards, yet the second turn runs inside the first.
  Mesh m;
  const int steps = 12;  // 2 turns of 6 sides
  for (int i = 0; i <= steps; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 6.0, r = 1.0 - 0.1 * i / 6.0;
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), 1.0);
  }
  for (unsigned i = 0; i < steps; ++i) {
    m.triangles.emplace_back(2 * i, 2 * i + 2, 2 * i + 3);
    m.triangles.emplace_back(2 * i, 2 * i + 3, 2 * i + 1);
  }
  const std::vector<ProxyMeshFinding> findings = check(m, {0.0, 0.0, 0.5});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_not_closed", "proxy_not_convex"));
  EXPECT_THAT(findings[1].message,
              HasSubstr("every edge bends outwards, yet the surface overlaps itself: vertex "));
}

TEST(ProxyMeshChecks, FlatMeshEnclosesNoVolume) {
  // Two triangles back to back: closed and consistently wound, yet no volume.
  const Mesh m{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}};
  const std::vector<ProxyMeshFinding> findings = check(m, {0.2, 0.2, 0.0});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_flat"));
  EXPECT_EQ(findings[0].value, 0.0);
}

TEST(ProxyMeshChecks, CaptureOutsideGivesTheDistance) {
  const std::vector<ProxyMeshFinding> findings = check(unitCube(), {2.0, 0.5, 0.5});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_misses_capture"));
  EXPECT_EQ(findings[0].value, 1.0);
  EXPECT_EQ(
      findings[0].message,
      "the capture point (2, 0.5, 0.5) lies 1 m outside the proxy, beyond the plane of face 6 "
      "(vertices 1, 2, 6)");
}

TEST(ProxyMeshChecks, CaptureOnAFaceIsOnTheBoundary) {
  const std::vector<ProxyMeshFinding> findings = check(unitCube(), {1.0, 0.5, 0.5});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_misses_capture"));
  EXPECT_EQ(findings[0].value, 0.0);
  EXPECT_LT(findings[0].limit, 0.0);
  EXPECT_EQ(findings[0].message,
            "the capture point (1, 0.5, 0.5) lies on the boundary of the proxy, 0 m from the plane "
            "of face 6 (vertices 1, 2, 6); it must be strictly inside");
  // Just inside the tolerance (1e-6 of the 1.73 m diagonal) is still on the boundary; beyond it
  // is inside.
  EXPECT_THAT(rules(check(unitCube(), {1.0 - 1e-6, 0.5, 0.5})),
              ElementsAre("proxy_misses_capture"));
  EXPECT_THAT(rules(check(unitCube(), {1.0 - 1e-5, 0.5, 0.5})), IsEmpty());
}

TEST(ProxyMeshChecks, BadInputThrows) {
  const Mesh cube = unitCube();
  const std::vector<glm::uvec3> pastTheEnd{glm::uvec3(0, 1, 99)};
  EXPECT_THROW(checkProxyMesh(cube.vertices, pastTheEnd, kCentre), std::invalid_argument);
  EXPECT_THROW(check(cube, {std::nan(""), 0.0, 0.0}), std::invalid_argument);
  ProxyMeshCheckOptions negative;
  negative.convexToleranceDegrees = -1.0;
  EXPECT_THROW(check(cube, kCentre, negative), std::invalid_argument);
}

// ---- ConvexProxy ----------------------------------------------------------------------------

ConvexProxy turnedBox() {
  BoxShape box;
  box.centerMeters = {3.0, -2.0, 1.5};
  box.halfExtentsMeters = {2.0, 1.0, 1.5};
  box.worldFromBox = glm::angleAxis(0.7, glm::normalize(glm::dvec3(0.2, 0.1, 1.0)));
  return convexFromBox(box);
}

TEST(ProxyMeshChecks, ConvexProxyFromBoxHasNoFindings) {
  EXPECT_THAT(rules(checkConvexProxy(turnedBox(), {3.0, -2.0, 1.5})), IsEmpty());
}

TEST(ProxyMeshChecks, ConvexProxyPlaneMovedOutLeavesFacesOffPlanes) {
  ConvexProxy proxy = turnedBox();
  proxy.planes[0].offsetMeters += 0.1;  // +x of the box: faces 0 and 1 lie on no plane now
  const std::vector<ProxyMeshFinding> findings = checkConvexProxy(proxy, {3.0, -2.0, 1.5});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_face_off_planes"));
  EXPECT_NEAR(findings[0].value, 0.1, 1e-12);
  EXPECT_THAT(findings[0].message,
              HasSubstr("2 triangles lie on none of the proxy's 6 planes; the worst, face "));
}

TEST(ProxyMeshChecks, ConvexProxyPlaneMovedInLeavesVerticesOutside) {
  ConvexProxy proxy = turnedBox();
  proxy.planes[0].offsetMeters -= 0.25;
  const std::vector<ProxyMeshFinding> findings = checkConvexProxy(proxy, {3.0, -2.0, 1.5});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_face_off_planes", "proxy_vertex_outside_planes"));
  EXPECT_NEAR(findings[1].value, 0.25, 1e-12);
  EXPECT_THAT(findings[1].message,
              HasSubstr("4 vertices lie outside the proxy's planes; the worst, vertex "));
  EXPECT_THAT(findings[1].message, HasSubstr(" m outside plane 0 (normal "));
}

TEST(ProxyMeshChecks, ConvexProxyNormalMustBeUnit) {
  ConvexProxy proxy = turnedBox();
  proxy.planes[3].normal *= 2.0;
  proxy.planes[3].offsetMeters *= 2.0;  // the same half-space, not normalized
  const std::vector<ProxyMeshFinding> findings = checkConvexProxy(proxy, {3.0, -2.0, 1.5});
  ASSERT_THAT(rules(findings), ElementsAre("proxy_bad_plane"));
  EXPECT_NEAR(findings[0].value, 2.0, 1e-12);
  EXPECT_THAT(findings[0].message, HasSubstr("plane 3 has the normal "));
}

}  // namespace
}  // namespace probeproxy
