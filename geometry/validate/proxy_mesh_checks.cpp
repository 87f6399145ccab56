#include "geometry/validate/proxy_mesh_checks.h"

#include "geometry/validate/weld_positions.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace probeproxy {

namespace {

struct MeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// ---- Text ------------------------------------------------------------------------------------

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", v == 0.0 ? 0.0 : v);  // no "-0"
  return text;
}

std::string point(glm::dvec3 p) {
  std::string text("(");  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) on that
  text += number(p.x);
  text += ", ";
  text += number(p.y);
  text += ", ";
  text += number(p.z);
  text += ")";
  return text;
}

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// "face 3", "faces 3 and 5", "faces 1, 2, 3, 4, 5, 6, 7, 8 and 4 more"
std::string faceList(const std::vector<std::uint32_t>& faces) {
  constexpr std::size_t kNamed = 8;
  if (faces.size() == 1) return "face " + std::to_string(faces[0]);
  std::string text = "faces ";
  const std::size_t named = std::min(faces.size(), kNamed);
  for (std::size_t i = 0; i < named; ++i) {
    if (i > 0) text += (i + 1 == named && faces.size() <= kNamed) ? " and " : ", ";
    text += std::to_string(faces[i]);
  }
  if (faces.size() > kNamed) text += " and " + std::to_string(faces.size() - kNamed) + " more";
  return text;
}

ProxyMeshFinding finding(std::string rule, std::string severity, double value, double limit,
                         std::string message, std::string hint) {
  return {std::move(rule), std::move(severity), value, limit, std::move(message), std::move(hint)};
}

// ---- Input -----------------------------------------------------------------------------------

void requireValid(const ProxyMeshCheckOptions& o) {
  const auto check = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0) {
      throw std::invalid_argument(std::string("checkProxyMesh: option ") + name +
                                  " must be finite and >= 0, got " + number(v));
    }
  };
  check(o.convexToleranceDegrees, "convexToleranceDegrees");
  check(o.weldToleranceRelative, "weldToleranceRelative");
  check(o.degenerateHeightRelative, "degenerateHeightRelative");
  check(o.planeToleranceRelative, "planeToleranceRelative");
}

bool isFinite(glm::dvec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Checks indices and coordinates; returns the referenced vertices in index order.
std::vector<std::uint32_t> referencedVertices(const std::vector<glm::dvec3>& vertices,
                                              const std::vector<glm::uvec3>& triangles,
                                              glm::dvec3 capture) {
  if (!isFinite(capture)) {
    throw std::invalid_argument("checkProxyMesh: capture point " + point(capture) +
                                " is not finite");
  }
  std::vector<char> used(vertices.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = triangles[t][k];
      if (v >= vertices.size()) {
        throw std::invalid_argument("checkProxyMesh: triangle " + std::to_string(t) +
                                    " refers to vertex " + std::to_string(v) + ", but there are " +
                                    std::to_string(vertices.size()) + " vertices");
      }
      if (!isFinite(vertices[v])) {
        throw std::invalid_argument("checkProxyMesh: vertex " + std::to_string(v) + " " +
                                    point(vertices[v]) + " is not finite");
      }
      used[v] = 1;
    }
  }
  std::vector<std::uint32_t> referenced;
  for (std::uint32_t v = 0; v < vertices.size(); ++v) {
    if (used[v]) referenced.push_back(v);
  }
  return referenced;
}

// The bounding-box diagonal of the referenced vertices: what every tolerance is relative to.
double meshSize(const std::vector<glm::dvec3>& vertices,
                const std::vector<std::uint32_t>& referenced) {
  if (referenced.empty()) return 0.0;
  glm::dvec3 lo = vertices[referenced[0]], hi = lo;
  for (std::uint32_t v : referenced) {
    lo = glm::min(lo, vertices[v]);
    hi = glm::max(hi, vertices[v]);
  }
  return glm::distance(lo, hi);
}

// ---- The checker -----------------------------------------------------------------------------

struct Face {
  std::array<std::uint32_t, 3> corner{};  // welded vertex ids, as wound in the input
  bool repeated = false;    // two corners weld together: no edges, left out of the topology
  bool degenerate = false;  // repeated, or its height is under the tolerance
  glm::dvec3 normal{0.0};   // unit, of the input winding; zero when degenerate
};

struct EdgeUse {
  std::uint32_t face;
  bool forward;  // the face runs along the edge from its lower to its higher vertex id
};

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;

EdgeKey edgeKey(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

class ProxyMeshChecker {
 public:
  ProxyMeshChecker(const std::vector<glm::dvec3>& vertices,
                   const std::vector<glm::uvec3>& triangles, glm::dvec3 capture,
                   const ProxyMeshCheckOptions& options)
      : V_(vertices), T_(triangles), capture_(capture), options_(options) {}

  std::vector<ProxyMeshFinding> run() {
    requireValid(options_);
    const std::vector<std::uint32_t> referenced = referencedVertices(V_, T_, capture_);
    if (T_.empty()) {
      out_.push_back(finding(
          "proxy_empty", "error", 0.0, 1.0,
          "the proxy mesh has no triangles (" + plural(V_.size(), "vertex", "vertices") + ")",
          "give the probe a closed convex mesh, or a box proxy"));
      return out_;
    }
    size_ = meshSize(V_, referenced);
    weldTolerance_ = options_.weldToleranceRelative * size_;
    heightTolerance_ = options_.degenerateHeightRelative * size_;
    planeTolerance_ = options_.planeToleranceRelative * size_;

    weld(referenced);
    classifyFaces();
    buildEdges();
    orient();
    buildOpenMesh();

    reportDegenerate();
    reportNotManifold();
    reportOpenEdges();
    reportWinding();
    reportPieces();
    if (checkVolume()) {
      checkConvexity();
      checkCapture();
    }
    return out_;
  }

 private:
  std::string faceName(std::uint32_t f) const {
    const glm::uvec3& t = T_[f];
    return "face " + std::to_string(f) + " (vertices " + std::to_string(t[0]) + ", " +
           std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
  }
  std::string vertexName(std::uint32_t v) const {
    return "vertex " + std::to_string(v) + " " + point(V_[v]);
  }

  void weld(const std::vector<std::uint32_t>& referenced) {
    std::vector<glm::dvec3> positions;
    positions.reserve(referenced.size());
    for (std::uint32_t v : referenced) positions.push_back(V_[v]);
    const std::vector<std::uint32_t> local = weldPositions(positions, weldTolerance_);
    weldedTo_.assign(V_.size(), kNone);
    for (std::size_t i = 0; i < referenced.size(); ++i)
      weldedTo_[referenced[i]] = referenced[local[i]];
  }

  void classifyFaces() {
    faces_.resize(T_.size());
    for (std::uint32_t f = 0; f < T_.size(); ++f) {
      Face& face = faces_[f];
      for (int k = 0; k < 3; ++k) face.corner[k] = weldedTo_[T_[f][k]];
      const auto [a, b, c] = face.corner;
      face.repeated = a == b || b == c || c == a;
      if (face.repeated) {
        face.degenerate = true;
        continue;
      }
      const glm::dvec3 pa = V_[a], pb = V_[b], pc = V_[c];
      const glm::dvec3 areaVector = glm::cross(pb - pa, pc - pa);  // 2 * area * normal
      const double twiceArea = glm::length(areaVector);
      const double longest =
          std::max({glm::distance(pa, pb), glm::distance(pb, pc), glm::distance(pc, pa)});
      face.degenerate = !(twiceArea > heightTolerance_ * longest) || twiceArea == 0.0;
      if (!face.degenerate) face.normal = areaVector / twiceArea;
    }
  }

  void buildEdges() {
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
      if (faces_[f].repeated) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = faces_[f].corner[k], b = faces_[f].corner[(k + 1) % 3];
        edges_[edgeKey(a, b)].push_back({f, a < b});
      }
    }
  }

  // Propagates the winding across every edge two faces share; in each connected piece the
  // larger class (by face count; the first face's class on a tie) is taken as right.
  void orient() {
    flipped_.assign(faces_.size(), false);
    oneSided_.assign(faces_.size(), false);
    std::vector<int> parity(faces_.size(), -1);
    std::vector<std::vector<std::uint32_t>> pieces;
    for (std::uint32_t seed = 0; seed < faces_.size(); ++seed) {
      if (faces_[seed].repeated || parity[seed] >= 0) continue;
      std::vector<std::uint32_t> piece;
      std::deque<std::uint32_t> queue{seed};
      parity[seed] = 0;
      bool conflict = false;
      while (!queue.empty()) {
        const std::uint32_t f = queue.front();
        queue.pop_front();
        piece.push_back(f);
        for (int k = 0; k < 3; ++k) {
          const auto& uses = edges_.at(edgeKey(faces_[f].corner[k], faces_[f].corner[(k + 1) % 3]));
          if (uses.size() != 2) continue;
          const EdgeUse& mine = uses[0].face == f ? uses[0] : uses[1];
          const EdgeUse& other = uses[0].face == f ? uses[1] : uses[0];
          // Neighbours wound alike run along their shared edge in opposite directions.
          const int want = parity[f] ^ (mine.forward == other.forward ? 1 : 0);
          if (parity[other.face] < 0) {
            parity[other.face] = want;
            queue.push_back(other.face);
          } else if (parity[other.face] != want) {
            conflict = true;
          }
        }
      }
      pieces.push_back(piece);
      if (conflict) {
        for (std::uint32_t f : piece) oneSided_[f] = true;
        continue;
      }
      const auto odd = static_cast<std::size_t>(std::count_if(
          piece.begin(), piece.end(), [&](std::uint32_t f) { return parity[f] == 1; }));
      const int right = odd > piece.size() - odd ? 1 : 0;
      for (std::uint32_t f : piece) flipped_[f] = parity[f] != right;
    }
    // Larger pieces go into the surface first: where a stray fin or a small piece shares an
    // edge or corner with the main surface, it is the fin that gets refused.
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    for (const auto& piece : pieces) order_.insert(order_.end(), piece.begin(), piece.end());
  }

  // The corners of face f as it goes into the surface: wound like its neighbours.
  std::array<std::uint32_t, 3> woundCorners(std::uint32_t f) const {
    std::array<std::uint32_t, 3> c = faces_[f].corner;
    if (flipped_[f]) std::swap(c[1], c[2]);
    return c;
  }

  struct Refusal {
    std::uint32_t face;
    std::string reason;
  };

  // Adds faces piece by piece in the order the orientation walk met them, so fans grow from
  // one side. A face
  // is refused, before OpenMesh would print its own complaint, where OpenMesh's add_face would
  // refuse it: a corner whose fan is already closed, or an edge that already has a face on this
  // side. Refused faces get a second chance once all others are in.
  void buildOpenMesh() {
    handleOf_.assign(V_.size(), OpenMesh::VertexHandle());
    mesh_.add_property(inputFace_);
    std::vector<std::uint32_t> pending = order_;
    std::vector<Refusal> refused;
    for (int pass = 0; pass < 2 && !pending.empty(); ++pass) {
      refused.clear();
      for (std::uint32_t f : pending) {
        std::string reason = tryAdd(f);
        if (!reason.empty()) refused.push_back({f, std::move(reason)});
      }
      if (refused.size() == pending.size()) break;
      pending.clear();
      for (const Refusal& r : refused) pending.push_back(r.face);
    }
    for (Refusal& r : refused) {
      if (oneSided_[r.face]) continue;  // reported as a one-sided surface instead
      refused_.push_back(std::move(r));
    }
    std::sort(refused_.begin(), refused_.end(),
              [](const Refusal& a, const Refusal& b) { return a.face < b.face; });
  }

  std::string tryAdd(std::uint32_t f) {
    const std::array<std::uint32_t, 3> c = woundCorners(f);
    std::array<OpenMesh::VertexHandle, 3> h;
    for (int k = 0; k < 3; ++k) {
      if (!handleOf_[c[k]].is_valid()) {
        const glm::dvec3 p = V_[c[k]];
        handleOf_[c[k]] = mesh_.add_vertex(TriMesh::Point(p.x, p.y, p.z));
        idOf_.push_back(c[k]);
      }
      h[k] = handleOf_[c[k]];
    }
    for (int k = 0; k < 3; ++k) {
      const OpenMesh::HalfedgeHandle he = mesh_.find_halfedge(h[k], h[(k + 1) % 3]);
      if (!he.is_valid() || mesh_.is_boundary(he)) continue;
      const std::uint32_t a = std::min(c[k], c[(k + 1) % 3]), b = std::max(c[k], c[(k + 1) % 3]);
      const std::size_t shared = edges_.at(edgeKey(a, b)).size();
      return "its edge from " + vertexName(a) + " to " + vertexName(b) +
             (shared > 2 ? " is shared by " + std::to_string(shared) + " faces"
                         : " already has a face wound the same way");
    }
    for (int k = 0; k < 3; ++k) {
      if (!mesh_.is_boundary(h[k])) {
        return "its " + vertexName(c[k]) +
               " already has a closed fan of faces (pieces touch there)";
      }
    }
    const OpenMesh::FaceHandle fh = mesh_.add_face(h[0], h[1], h[2]);
    if (!fh.is_valid()) return "its corners cannot be linked into one surface";
    mesh_.property(inputFace_, fh) = f;
    return {};
  }

  // ---- Topology findings ----

  void reportDegenerate() {
    std::vector<std::uint32_t> list;
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
      if (faces_[f].degenerate) list.push_back(f);
    }
    if (list.empty()) return;
    out_.push_back(finding("proxy_degenerate_face", "warning", static_cast<double>(list.size()),
                           0.0,
                           plural(list.size(), "face has", "faces have") +
                               " zero area (height under " + number(heightTolerance_) +
                               " m): " + faceList(list) + "; the first is " + faceName(list[0]),
                           "delete zero-area faces or merge their corners (Blender: Mesh > Clean "
                           "Up > Degenerate Dissolve)"));
  }

  void reportNotManifold() {
    if (refused_.empty()) return;
    std::vector<std::uint32_t> list;
    for (const Refusal& r : refused_) list.push_back(r.face);
    out_.push_back(finding(
        "proxy_not_manifold", "error", static_cast<double>(list.size()), 0.0,
        plural(list.size(), "face does", "faces do") + " not fit one 2-manifold surface and " +
            (list.size() == 1 ? "is" : "are") + " left out of the other checks: " + faceList(list) +
            "; " + faceName(list[0]) + ": " + refused_[0].reason,
        "every edge must join exactly two faces and every corner one fan of faces: delete fins "
        "and inner walls, and separate pieces that touch"));
  }

  void reportOpenEdges() {
    std::vector<EdgeKey> open;
    for (const auto& [key, uses] : edges_) {
      if (uses.size() == 1) open.push_back(key);
    }
    if (open.empty()) return;
    // Holes: connected groups of open edges.
    std::map<std::uint32_t, std::uint32_t> parent;
    const auto root = [&](std::uint32_t v) {
      while (parent.at(v) != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for (const EdgeKey& e : open) {
      parent.emplace(e.first, e.first);
      parent.emplace(e.second, e.second);
    }
    std::size_t holes = parent.size();
    for (const EdgeKey& e : open) {
      const std::uint32_t a = root(e.first), b = root(e.second);
      if (a != b) {
        parent[std::max(a, b)] = std::min(a, b);
        --holes;
      }
    }
    out_.push_back(finding(
        "proxy_not_closed", "error", static_cast<double>(open.size()), 0.0,
        "the mesh is not closed: " + plural(open.size(), "open edge", "open edges") +
            " (used by one face only) around " + plural(holes, "hole", "holes") +
            "; the first joins " + vertexName(open[0].first) + " and " + vertexName(open[0].second),
        "fill the holes so the proxy encloses a volume (Blender: Select > Select All by Trait > "
        "Non Manifold, then Face > Fill)"));
  }

  void reportWinding() {
    std::vector<std::uint32_t> flippedList, oneSidedList;
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
      if (flipped_[f]) flippedList.push_back(f);
      if (oneSided_[f]) oneSidedList.push_back(f);
    }
    const std::string hint =
        "wind every face counter-clockwise seen from outside (Blender: Mesh > Normals > "
        "Recalculate Outside)";
    if (!flippedList.empty()) {
      out_.push_back(
          finding("proxy_not_oriented", "error", static_cast<double>(flippedList.size()), 0.0,
                  plural(flippedList.size(), "face is", "faces are") + " wound against " +
                      (flippedList.size() == 1 ? "its" : "their") + " neighbours: " +
                      faceList(flippedList) + "; the first is " + faceName(flippedList[0]),
                  hint));
    }
    if (!oneSidedList.empty()) {
      out_.push_back(
          finding("proxy_not_oriented", "error", static_cast<double>(oneSidedList.size()), 0.0,
                  "the surface through " + faceList(oneSidedList) +
                      " is one-sided (like a Moebius strip): no winding makes all neighbours agree",
                  "rebuild that part as a closed two-sided surface; " + hint));
    }
  }

  // ---- Geometry findings, on the faces that joined the surface, wound as their neighbours ----

  // Signed volume about the centroid (inside any convex mesh, so every face of an outward
  // convex mesh adds a positive amount even when it is open). False when nothing is left to
  // check geometrically.
  bool checkVolume() {
    std::size_t withArea = 0;
    for (const auto fh : mesh_.faces())
      withArea += faces_[mesh_.property(inputFace_, fh)].degenerate ? 0 : 1;
    if (withArea == 0) {
      out_.push_back(finding("proxy_empty", "error", 0.0, 1.0,
                             "none of the proxy mesh's " +
                                 plural(T_.size(), "triangle", "triangles") +
                                 " has an area and joins the surface",
                             "give the probe a closed convex mesh, or a box proxy"));
      return false;
    }
    glm::dvec3 centroid(0.0);
    std::size_t count = 0;
    for (const auto vh : mesh_.vertices()) {
      if (mesh_.is_isolated(vh)) continue;
      centroid += V_[idOf_[vh.idx()]];
      ++count;
    }
    centroid /= static_cast<double>(count);
    double volume = 0.0;
    for (const auto fh : mesh_.faces()) {
      const auto c = woundCorners(mesh_.property(inputFace_, fh));
      const double term =
          glm::dot(V_[c[0]] - centroid, glm::cross(V_[c[1]] - centroid, V_[c[2]] - centroid)) / 6.0;
      volume += term;
    }
    // A slab thinner than the plane tolerance across the whole mesh.
    const double volumeTolerance = planeTolerance_ * size_ * size_;
    if (std::abs(volume) <= volumeTolerance) {
      out_.push_back(finding("proxy_flat", "error", std::abs(volume), volumeTolerance,
                             "the mesh encloses no volume (" + number(volume) +
                                 " m^3): its faces lie on top of each other",
                             "give the proxy depth in every direction around the capture point"));
      return false;
    }
    outward_ = volume > 0.0 ? 1.0 : -1.0;
    if (volume < 0.0) {
      out_.push_back(
          finding("proxy_inward_faces", "error", volume, 0.0,
                  "faces point inwards: the signed volume is " + number(volume) +
                      " m^3 (faces wound clockwise seen from outside)",
                  "flip every face (Blender: Mesh > Normals > Flip, or Recalculate Outside)"));
    }
    return true;
  }

  // The outward unit normal of an accepted face with an area.
  glm::dvec3 outwardNormal(std::uint32_t f) const {
    return faces_[f].normal * (flipped_[f] ? -outward_ : outward_);
  }

  void checkConvexity() {
    // Bend of each edge between two faces with an area: positive where the surface turns away
    // from the inside (convex), negative where it folds in.
    double worstBend = 0.0;
    std::size_t concave = 0;
    std::uint32_t worstA = 0, worstB = 0, worstF0 = 0, worstF1 = 0;
    for (const auto eh : mesh_.edges()) {
      if (mesh_.is_boundary(eh)) continue;
      const auto h0 = mesh_.halfedge_handle(eh, 0);
      const std::uint32_t f0 = mesh_.property(inputFace_, mesh_.face_handle(h0));
      const std::uint32_t f1 = mesh_.property(inputFace_, mesh_.opposite_face_handle(h0));
      if (faces_[f0].degenerate || faces_[f1].degenerate) continue;
      const std::uint32_t from = idOf_[mesh_.from_vertex_handle(h0).idx()];
      const std::uint32_t to = idOf_[mesh_.to_vertex_handle(h0).idx()];
      // f0 runs along the edge from -> to in the surface's winding, to -> from if that winding
      // is inward.
      const glm::dvec3 along = glm::normalize(V_[to] - V_[from]) * outward_;
      const glm::dvec3 n0 = outwardNormal(f0), n1 = outwardNormal(f1);
      const double bend = std::atan2(glm::dot(glm::cross(n0, n1), along), glm::dot(n0, n1)) *
                          180.0 / std::numbers::pi;
      if (-bend > options_.convexToleranceDegrees) {
        ++concave;
        if (bend < worstBend) {
          worstBend = bend;
          worstA = std::min(from, to);
          worstB = std::max(from, to);
          worstF0 = std::min(f0, f1);
          worstF1 = std::max(f0, f1);
        }
      }
    }
    if (concave > 0) {
      out_.push_back(finding(
          "proxy_concave_edge", "error", -worstBend, options_.convexToleranceDegrees,
          plural(concave, "edge bends", "edges bend") + " inwards; the worst, from " +
              vertexName(worstA) + " to " + vertexName(worstB) + " between faces " +
              std::to_string(worstF0) + " and " + std::to_string(worstF1) + ", bends inwards by " +
              number(-worstBend) + " degrees",
          "a proxy must be convex: use the mesh's convex hull (Blender: Mesh > Convex Hull) or "
          "split the volume between several probes"));
      return;
    }

    // Locally convex everywhere. A closed, connected, locally convex surface bounds a convex
    // body (Hadamard, van Heijenoort); what is left to catch is an open surface that spirals
    // over itself or a vertex whose fan wraps around twice. The test is every vertex against
    // every face plane, so it is skipped on meshes too large for it (over 1e8 vertex-face
    // pairs, ~0.1 s: far beyond hand-made proxies).
    constexpr double kMaxPairs = 1e8;
    if (pieces_ > 1) return;  // reported as separate pieces
    std::vector<std::uint32_t> used, withArea;
    for (const auto vh : mesh_.vertices()) {
      if (!mesh_.is_isolated(vh)) used.push_back(idOf_[vh.idx()]);
    }
    for (const auto fh : mesh_.faces()) {
      const std::uint32_t f = mesh_.property(inputFace_, fh);
      if (!faces_[f].degenerate) withArea.push_back(f);
    }
    if (static_cast<double>(used.size()) * static_cast<double>(withArea.size()) > kMaxPairs) return;
    std::sort(used.begin(), used.end());  // ties go to the lowest face, then vertex index
    std::sort(withArea.begin(), withArea.end());
    std::vector<glm::dvec3> positions;
    positions.reserve(used.size());
    for (std::uint32_t v : used) positions.push_back(V_[v]);
    double worst = -std::numeric_limits<double>::infinity();
    std::uint32_t worstVertex = 0, worstFace = 0;
    for (std::uint32_t f : withArea) {
      const glm::dvec3 n = outwardNormal(f), anchor = V_[faces_[f].corner[0]];
      const double offset = glm::dot(n, anchor);
      double faceWorst = -std::numeric_limits<double>::infinity();
      std::size_t faceWorstVertex = 0;
      for (std::size_t i = 0; i < positions.size(); ++i) {
        const double outside = glm::dot(n, positions[i]) - offset;
        if (outside > faceWorst) {
          faceWorst = outside;
          faceWorstVertex = i;
        }
      }
      if (faceWorst > worst) {
        worst = faceWorst;
        worstVertex = used[faceWorstVertex];
        worstFace = f;
      }
    }
    // Bends within the angle tolerance let a far vertex sit a little outside a face's plane.
    const double tolerance = planeTolerance_ + size_ * std::sin(options_.convexToleranceDegrees *
                                                                std::numbers::pi / 180.0);
    if (worst <= tolerance) return;
    out_.push_back(finding(
        "proxy_not_convex", "error", worst, tolerance,
        "every edge bends outwards, yet the surface overlaps itself: " + vertexName(worstVertex) +
            " lies " + number(worst) + " m outside the plane of " + faceName(worstFace),
        "rebuild the proxy as its convex hull (Blender: Mesh > Convex Hull)"));
  }

  // Connected pieces of the surface (faces joined across shared edges).
  void reportPieces() {
    std::vector<char> seen(mesh_.n_faces(), 0);
    std::vector<std::uint32_t> firstFaces;
    for (const auto seed : mesh_.faces()) {
      if (seen[seed.idx()]) continue;
      std::uint32_t first = mesh_.property(inputFace_, seed);
      std::vector<OpenMesh::FaceHandle> stack{seed};
      seen[seed.idx()] = 1;
      while (!stack.empty()) {
        const OpenMesh::FaceHandle f = stack.back();
        stack.pop_back();
        first = std::min(first, mesh_.property(inputFace_, f));
        for (const auto g : mesh_.ff_range(f)) {
          if (!seen[g.idx()]) {
            seen[g.idx()] = 1;
            stack.push_back(g);
          }
        }
      }
      firstFaces.push_back(first);
    }
    pieces_ = firstFaces.size();
    if (pieces_ <= 1) return;
    std::sort(firstFaces.begin(), firstFaces.end());
    out_.push_back(finding(
        "proxy_separate_pieces", "error", static_cast<double>(pieces_), 1.0,
        "the mesh is " + std::to_string(pieces_) +
            " separate pieces that share no edge; the first face of each: " + faceList(firstFaces),
        "one proxy is one convex piece: join the pieces (weld their seams), give each its own "
        "probe, or use their convex hull"));
  }

  void checkCapture() {
    double worst = -std::numeric_limits<double>::infinity();
    std::uint32_t worstFace = kNone;
    for (const auto fh : mesh_.faces()) {
      const std::uint32_t f = mesh_.property(inputFace_, fh);
      if (faces_[f].degenerate) continue;
      const double outside = glm::dot(outwardNormal(f), capture_ - V_[faces_[f].corner[0]]);
      if (outside > worst || (outside == worst && f < worstFace)) {
        worst = outside;
        worstFace = f;
      }
    }
    if (worst < -planeTolerance_) return;
    const bool onBoundary = worst <= planeTolerance_;
    const std::string where = "the capture point " + point(capture_);
    out_.push_back(finding(
        "proxy_misses_capture", "error", worst, -planeTolerance_,
        onBoundary
            ? where + " lies on the boundary of the proxy, " + number(std::abs(worst)) +
                  " m from the plane of " + faceName(worstFace) + "; it must be strictly inside"
            : where + " lies " + number(worst) + " m outside the proxy, beyond the plane of " +
                  faceName(worstFace),
        onBoundary ? "move the capture point into the proxy, away from its faces"
                   : "move the capture point inside the proxy, or grow the proxy around it"));
  }

  const std::vector<glm::dvec3>& V_;
  const std::vector<glm::uvec3>& T_;
  const glm::dvec3 capture_;
  const ProxyMeshCheckOptions options_;

  double size_ = 0.0;  // bounding-box diagonal of the referenced vertices, metres
  double weldTolerance_ = 0.0, heightTolerance_ = 0.0, planeTolerance_ = 0.0;
  double outward_ = 1.0;  // -1 when the surface's winding points inwards
  std::size_t pieces_ = 0;
  std::vector<std::uint32_t> weldedTo_;            // input vertex -> welded vertex id
  std::vector<Face> faces_;                        // per input triangle
  std::map<EdgeKey, std::vector<EdgeUse>> edges_;  // ordered: reports are deterministic
  std::vector<bool> flipped_, oneSided_;           // per input triangle
  std::vector<std::uint32_t> order_;               // faces in orientation-walk order
  std::vector<Refusal> refused_;                   // faces left out of the surface
  TriMesh mesh_;
  OpenMesh::FPropHandleT<std::uint32_t> inputFace_;
  std::vector<OpenMesh::VertexHandle> handleOf_;  // welded vertex id -> OpenMesh vertex
  std::vector<std::uint32_t> idOf_;               // OpenMesh vertex index -> welded vertex id
  std::vector<ProxyMeshFinding> out_;
};

}  // namespace

std::vector<ProxyMeshFinding> checkProxyMesh(const std::vector<glm::dvec3>& verticesMeters,
                                             const std::vector<glm::uvec3>& triangles,
                                             glm::dvec3 captureMeters,
                                             const ProxyMeshCheckOptions& options) {
  return ProxyMeshChecker(verticesMeters, triangles, captureMeters, options).run();
}

std::vector<ProxyMeshFinding> checkProxyMesh(const LevelMesh& mesh, glm::dvec3 captureMeters,
                                             const ProxyMeshCheckOptions& options) {
  const std::vector<glm::dvec3> vertices(mesh.positionsMeters.begin(), mesh.positionsMeters.end());
  return checkProxyMesh(vertices, mesh.triangles, captureMeters, options);
}

std::vector<ProxyMeshFinding> checkConvexProxy(const ConvexProxy& proxy, glm::dvec3 captureMeters,
                                               const ProxyMeshCheckOptions& options) {
  std::vector<ProxyMeshFinding> out =
      checkProxyMesh(proxy.verticesMeters, proxy.triangles, captureMeters, options);
  if (proxy.triangles.empty()) return out;
  const std::vector<glm::dvec3>& V = proxy.verticesMeters;
  const std::vector<std::uint32_t> referenced =
      referencedVertices(V, proxy.triangles, captureMeters);
  const double tolerance = options.planeToleranceRelative * meshSize(V, referenced);
  const std::string rebuildHint =
      "rebuild the triangles from the planes (the runtime intersects rays with the planes and "
      "rasterizes the triangles: both must describe one volume)";

  // Planes, made unit for the comparisons below; unusable ones are reported and skipped.
  if (proxy.planes.empty()) {
    out.push_back(finding("proxy_bad_plane", "error", 0.0, 1.0,
                          "the proxy has " +
                              plural(proxy.triangles.size(), "triangle", "triangles") +
                              " but no planes",
                          rebuildHint));
    return out;
  }
  std::vector<ProxyPlane> planes;
  std::vector<std::size_t> planeIndex;
  for (std::size_t p = 0; p < proxy.planes.size(); ++p) {
    const ProxyPlane& plane = proxy.planes[p];
    const double length = glm::length(plane.normal);
    const bool finite = isFinite(plane.normal) && std::isfinite(plane.offsetMeters);
    if (!finite || std::abs(length - 1.0) > 1e-6) {
      out.push_back(
          finding("proxy_bad_plane", "error", finite ? length : 0.0, 1.0,
                  "plane " + std::to_string(p) + " has the normal " + point(plane.normal) +
                      " (length " + number(length) + ") and offset " + number(plane.offsetMeters) +
                      " m; normals must be unit vectors pointing out of the proxy",
                  "normalize the plane: divide its normal and offset by the normal's length"));
    }
    if (!finite || !(length > 0.0)) continue;
    planes.push_back({plane.normal / length, plane.offsetMeters / length});
    planeIndex.push_back(p);
  }
  if (planes.empty()) return out;

  const auto planeName = [&](std::size_t i) {
    return "plane " + std::to_string(planeIndex[i]) + " (normal " +
           point(proxy.planes[planeIndex[i]].normal) + ", offset " +
           number(proxy.planes[planeIndex[i]].offsetMeters) + " m)";
  };

  // Every triangle on a plane: its corners' largest distance from the nearest plane.
  std::size_t offFaces = 0;
  double worstOff = -1.0;
  std::size_t worstFace = 0, worstFacePlane = 0;
  for (std::size_t f = 0; f < proxy.triangles.size(); ++f) {
    double nearest = std::numeric_limits<double>::infinity();
    std::size_t nearestPlane = 0;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      double off = 0.0;
      for (int k = 0; k < 3; ++k) {
        off = std::max(off, std::abs(glm::dot(planes[p].normal, V[proxy.triangles[f][k]]) -
                                     planes[p].offsetMeters));
      }
      if (off < nearest) {
        nearest = off;
        nearestPlane = p;
      }
    }
    if (nearest <= tolerance) continue;
    ++offFaces;
    if (nearest > worstOff) {
      worstOff = nearest;
      worstFace = f;
      worstFacePlane = nearestPlane;
    }
  }
  if (offFaces > 0) {
    const glm::uvec3& t = proxy.triangles[worstFace];
    out.push_back(
        finding("proxy_face_off_planes", "error", worstOff, tolerance,
                plural(offFaces, "triangle lies", "triangles lie") + " on none of the proxy's " +
                    plural(proxy.planes.size(), "plane", "planes") + "; the worst, face " +
                    std::to_string(worstFace) + " (vertices " + std::to_string(t[0]) + ", " +
                    std::to_string(t[1]) + ", " + std::to_string(t[2]) + "), is " +
                    number(worstOff) + " m from the nearest, " + planeName(worstFacePlane),
                rebuildHint));
  }

  // Every vertex inside every plane.
  std::size_t outsideVertices = 0;
  double worstOutside = -1.0;
  std::uint32_t worstVertex = 0;
  std::size_t worstVertexPlane = 0;
  for (std::uint32_t v : referenced) {
    double outside = -std::numeric_limits<double>::infinity();
    std::size_t plane = 0;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      const double d = glm::dot(planes[p].normal, V[v]) - planes[p].offsetMeters;
      if (d > outside) {
        outside = d;
        plane = p;
      }
    }
    if (outside <= tolerance) continue;
    ++outsideVertices;
    if (outside > worstOutside) {
      worstOutside = outside;
      worstVertex = v;
      worstVertexPlane = plane;
    }
  }
  if (outsideVertices > 0) {
    out.push_back(finding("proxy_vertex_outside_planes", "error", worstOutside, tolerance,
                          plural(outsideVertices, "vertex lies", "vertices lie") +
                              " outside the proxy's planes; the worst, vertex " +
                              std::to_string(worstVertex) + " " + point(V[worstVertex]) + ", is " +
                              number(worstOutside) + " m outside " + planeName(worstVertexPlane),
                          rebuildHint));
  }
  return out;
}

}  // namespace probeproxy
