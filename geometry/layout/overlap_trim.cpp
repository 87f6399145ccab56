#include "geometry/layout/overlap_trim.h"

#include "core/blend/weight_continuity.h"
#include "geometry/layout/layout_influence.h"
#include "geometry/survey/blended_error.h"
#include "geometry/validate/camera_space.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

namespace probeproxy {

namespace {

// A trimmed band keeps this many gaps: walked floor lies within a gap of some range, so the
// band still reaches it; and across a gap of g between two ranges a band of b >= g keeps the
// steepest change at 1 / (g (1 - g / 2b)) <= 2 per metre, validate's limit (layout_influence.h).
constexpr double kLeastTrimmedBandOverGap = 1.0;

// A grid point stands for its cell (the rule's sample, and validate's grid moves when a trim
// moves the volumes' bounds): the face stops short of the whole cell, and this much more, so
// the scene file's rounding cannot bring the point back in.
constexpr double kFaceClearanceMeters = 1e-3;

// The blend's steepest change near a trim is compared on this grid: validate's is 1 cm on a
// small level and 5-7 cm on a corpus map (its budget of points per height).
constexpr double kBlendCheckGridMeters = 0.05;

// A band trim (side 0: the half extent becomes `meters`) or, for a fill whose faces may move,
// one face moved in by `meters` with its band (side -1 low, +1 high).
struct Cut {
  std::size_t volume = 0;  // index into the volumes, kept first
  int axis = 0;            // 0 (x) or 1 (y): storeys meet through a short band already
  int side = 0;
  double meters = 0.0;
  auto key() const { return std::tie(volume, axis, side, meters); }
  bool operator<(const Cut& o) const { return key() < o.key(); }
};

BoxInfluence cutBox(BoxInfluence box, const Cut& cut) {
  if (cut.side != 0) return withFaceMovedIn(box, cut.axis, cut.side, cut.meters);
  box.halfExtentsMeters[cut.axis] = cut.meters;
  return box;
}

// The half extent along `axis` that leaves the cell of `p` out of the box, if the band keeps
// its least width and the box its capture point (a fill's capture may stand in its band, on the
// side the trim cuts).
std::optional<double> halfExtentLeaving(const BoxInfluence& box, int axis, glm::dvec3 p,
                                        glm::dvec3 cellMeters, double gapMeters,
                                        glm::dvec3 captureMeters) {
  const double half =
      std::abs(p[axis] - box.centerMeters[axis]) - 0.5 * cellMeters[axis] - kFaceClearanceMeters;
  const double band = half - box.innerHalfExtentsMeters[axis];
  if (band < kLeastTrimmedBandOverGap * gapMeters) return std::nullopt;
  if (half < std::abs(captureMeters[axis] - box.centerMeters[axis]) + kCaptureMarginMeters)
    return std::nullopt;
  return half;
}

// How far the `side` face along `axis` moves in to leave the cell of `p` out of the box, if the
// inner range keeps some width and the box its capture point.
std::optional<double> faceCutLeaving(const BoxInfluence& box, int axis, int side, glm::dvec3 p,
                                     glm::dvec3 cellMeters, glm::dvec3 captureMeters) {
  const double face = box.centerMeters[axis] + side * box.halfExtentsMeters[axis];
  const double inside = side * (face - p[axis]);
  const Cut cut{0, axis, side, inside + 0.5 * cellMeters[axis] + kFaceClearanceMeters};
  const BoxInfluence moved = cutBox(box, cut);
  if (moved.innerHalfExtentsMeters[axis] <= 0.0 || !insideInfluence(moved, captureMeters))
    return std::nullopt;
  return cut.meters;
}

// Every walked cell the trim gives up (its point lifted as the survey lifts it) in some other
// volume.
bool floorStaysCovered(const WalkableFloor& walked, std::span<const InfluenceVolume> volumes,
                       std::size_t trimmed, const BoxInfluence& after) {
  for (const FloorCell& cell : walked.cells) {
    const glm::dvec3 p = cell.pointMeters + glm::dvec3(0.0, 0.0, kBlendLiftMeters);
    if (!insideInfluence(volumes[trimmed], p) || insideInfluence(after, p)) continue;
    bool covered = false;
    for (std::size_t v = 0; v < volumes.size() && !covered; ++v)
      covered = v != trimmed && insideInfluence(volumes[v], p);
    if (!covered) return false;
  }
  return true;
}

// Where a camera can be on the rows of the blend's grids, remembered: a trim's blend is
// compared before and after on the same rows, and a refused trim's rows come up again.
class CameraRows {
 public:
  CameraRows(const LevelRayCaster& level, const WalkableFloor& walked, double headRoomMeters)
      : level_(level), walked_(walked), headRoomMeters_(headRoomMeters) {}
  void mark(std::span<const glm::dvec3> points, std::span<char> reachable) {
    const glm::dvec3 first = points.empty() ? glm::dvec3(0.0) : points.front();
    std::vector<char>& row = rows_[{first.x, first.y, first.z, points.size()}];
    if (row.empty()) {
      row.assign(points.size(), 0);
      markCameraSpace(level_, walked_, headRoomMeters_, points, row);
    }
    std::copy(row.begin(), row.end(), reachable.begin());
  }
  ReachableMask mask() {
    return [this](std::span<const glm::dvec3> points, std::span<char> out) { mark(points, out); };
  }

 private:
  const LevelRayCaster& level_;
  const WalkableFloor& walked_;
  double headRoomMeters_;
  std::map<std::tuple<double, double, double, std::size_t>, std::vector<char>> rows_;
};

// The volumes reaching into the box (lo, hi): the others weigh nothing there.
std::vector<InfluenceVolume> volumesNear(std::span<const InfluenceVolume> volumes, glm::dvec3 lo,
                                         glm::dvec3 hi) {
  std::vector<InfluenceVolume> near;
  for (const InfluenceVolume& v : volumes) {
    glm::dvec3 vlo, vhi;
    influenceBounds(v, vlo, vhi);
    if (glm::all(glm::lessThan(vlo, hi)) && glm::all(glm::lessThan(lo, vhi))) near.push_back(v);
  }
  return near;
}

// The steepest change of any weight per centimetre on a grid over the plan rectangle (lo, hi),
// at the capture heights strictly inside (zLo, zHi), where a camera can be.
double steepestChangeOn(std::span<const InfluenceVolume> near, glm::dvec2 lo, glm::dvec2 hi,
                        double zLo, double zHi, std::span<const double> heights, CameraRows& rows) {
  double steepest = 0.0;
  for (double z : heights) {
    if (z <= zLo || z >= zHi) continue;
    const WeightGrid grid{lo, hi, z, kBlendCheckGridMeters};
    const WeightContinuity c = measureWeightContinuity(near, grid, {}, rows.mask());
    steepest = std::max(steepest, c.largestJump / (100.0 * kBlendCheckGridMeters));
  }
  return steepest;
}

// The steepest change over the trimmed volume's bands along the trimmed axis (where its weight
// changes), at the capture heights its box spans. Only volumes near there take part.
double steepestChangeAlong(std::span<const InfluenceVolume> volumes, const BoxInfluence& box,
                           int axis, std::span<const double> heights, CameraRows& rows) {
  const glm::dvec3 lo = box.centerMeters - box.halfExtentsMeters;
  const glm::dvec3 hi = box.centerMeters + box.halfExtentsMeters;
  const std::vector<InfluenceVolume> near = volumesNear(volumes, lo, hi);
  const double innerLo = box.centerMeters[axis] - box.innerHalfExtentsMeters[axis];
  const double innerHi = box.centerMeters[axis] + box.innerHalfExtentsMeters[axis];
  double steepest = 0.0;
  for (auto [from, to] : {std::pair{lo[axis], innerLo}, std::pair{innerHi, hi[axis]}}) {
    glm::dvec2 bandLo(lo), bandHi(hi);
    bandLo[axis] = from, bandHi[axis] = to;
    steepest =
        std::max(steepest, steepestChangeOn(near, bandLo, bandHi, lo.z, hi.z, heights, rows));
  }
  return steepest;
}

// Whether the blend over the volume's bands along `axis` turns, with its box `trimmed`, no
// steeper than validate's limit, or than it did.
bool blendStaysSmooth(std::vector<InfluenceVolume>& volumes, std::size_t v,
                      const BoxInfluence& trimmed, int axis, std::span<const double> heights,
                      CameraRows& rows, double limitPerCentimeter) {
  const BoxInfluence old = std::get<BoxInfluence>(volumes[v]);
  const double before = steepestChangeAlong(volumes, old, axis, heights, rows);
  volumes[v] = trimmed;
  const double after = steepestChangeAlong(volumes, old, axis, heights, rows);
  volumes[v] = old;
  return after <= std::max(before, limitPerCentimeter);
}

// The steepest change over the box, at the capture heights it spans, with the volumes near it.
double steepestChangeOver(std::span<const InfluenceVolume> volumes, const BoxInfluence& box,
                          std::span<const double> heights, CameraRows& rows) {
  const glm::dvec3 lo = box.centerMeters - box.halfExtentsMeters;
  const glm::dvec3 hi = box.centerMeters + box.halfExtentsMeters;
  return steepestChangeOn(volumesNear(volumes, lo, hi), glm::dvec2(lo), glm::dvec2(hi), lo.z, hi.z,
                          heights, rows);
}

// A fill's face moves instead of the fill going (run_layout drops a fill still in a crowd):
// whether over its box the blend turns no steeper than validate's limit, or than it would
// without the fill (bloodprison's fill over a ramp's range turns at 0.025 per cm once its face
// moves 2 m; without it two bands' ends touch there: 0.2 per cm).
bool blendBetterThanWithout(std::vector<InfluenceVolume>& volumes, std::size_t v,
                            const BoxInfluence& moved, std::span<const double> heights,
                            CameraRows& rows, double limitPerCentimeter) {
  const BoxInfluence old = std::get<BoxInfluence>(volumes[v]);
  volumes[v] = moved;
  const double after = steepestChangeOver(volumes, old, heights, rows);
  volumes.erase(volumes.begin() + static_cast<std::ptrdiff_t>(v));
  const double without = steepestChangeOver(volumes, old, heights, rows);
  volumes.insert(volumes.begin() + static_cast<std::ptrdiff_t>(v), old);
  return after <= std::max(without, limitPerCentimeter);
}

// The trim that frees the most points for the least band, none refused before, or when none is
// left the face move that does. Per volume, axis and side each point asks for a half extent (or
// a face's cut); a cut to one of them frees every point asking for as much or less.
std::optional<Cut> nextCut(std::span<const OverlapPoint> points,
                           std::span<const InfluenceVolume> volumes, std::size_t keptCount,
                           std::span<const LayoutProbe> probes,
                           const std::set<std::size_t>& facesMove, glm::dvec3 cellMeters,
                           double gapMeters, const std::set<Cut>& refused) {
  std::map<std::tuple<std::size_t, int, int>, std::vector<double>> asked;
  for (const OverlapPoint& p : points) {
    for (int index : p.volumes) {
      const std::size_t v = static_cast<std::size_t>(index);
      if (v < keptCount || !innerRangeOf(volumes[v])) continue;  // the layout's own boxes only
      const BoxInfluence& box = std::get<BoxInfluence>(volumes[v]);
      const glm::dvec3 capture = probes[v - keptCount].captureMeters;
      for (int axis : {0, 1}) {
        if (auto half = halfExtentLeaving(box, axis, p.pointMeters, cellMeters, gapMeters, capture))
          asked[{v, axis, 0}].push_back(*half);
        if (!facesMove.count(v - keptCount)) continue;
        for (int side : {-1, 1})
          if (auto cut = faceCutLeaving(box, axis, side, p.pointMeters, cellMeters, capture))
            asked[{v, axis, side}].push_back(*cut);
      }
    }
  }
  // Band trims before face moves (a fill's face moved first kept bloodprison's trims of the
  // bands around it from passing the blend check), then the most points freed, then the least
  // cut; the first of equals.
  std::optional<Cut> best;
  std::tuple<bool, std::ptrdiff_t, double> bestRank;
  for (auto& [which, values] : asked) {
    const auto [v, axis, side] = which;
    // Band trims ask for half extents (less is more cut), faces for cuts.
    if (side == 0)
      std::sort(values.begin(), values.end(), std::greater<>());
    else
      std::sort(values.begin(), values.end());
    const double now = std::get<BoxInfluence>(volumes[v]).halfExtentsMeters[axis];
    for (std::size_t j = 0; j < values.size(); ++j) {
      if (j + 1 < values.size() && values[j + 1] == values[j]) continue;  // frees those too
      const Cut cut{v, axis, side, values[j]};
      if (refused.count(cut)) continue;
      const auto freed = static_cast<std::ptrdiff_t>(j + 1);
      const std::tuple rank{side != 0, -freed, side == 0 ? now - values[j] : values[j]};
      if (!best || rank < bestRank) best = cut, bestRank = rank;
    }
  }
  return best;
}

}  // namespace

std::vector<OverlapPoint> trimBandsOverOverlapLimit(const LevelRayCaster& level,
                                                    const WalkableFloor& walked, double gapMeters,
                                                    const ValidateOptions& limits,
                                                    std::span<const InfluenceVolume> kept,
                                                    std::vector<LayoutProbe>& probes,
                                                    const std::set<std::size_t>& facesMove) {
  std::vector<InfluenceVolume> volumes(kept.begin(), kept.end());
  // Every capture height: a superset of validate's weight_jump planes (one a 10 cm band of
  // them, camera_planes.h), so a trim is held to at least what validate checks. On hilly ground
  // these are as many as the probes, and the trims' checks grow with them (the generated 1 ha
  // town: 8 s of its 130).
  std::vector<double> heights;
  for (const LayoutProbe& p : probes) {
    volumes.push_back(p.influence);
    heights.push_back(p.captureMeters.z);
  }
  std::sort(heights.begin(), heights.end());
  heights.erase(std::unique(heights.begin(), heights.end()), heights.end());
  OverlapPoints over = overlapsOverLimit(volumes, level, walked, limits);
  std::set<Cut> refused;
  CameraRows rows(level, walked, limits.cameraHeadRoomMeters);
  std::vector<OverlapPoint>& points = over.points;
  while (!points.empty()) {
    const std::optional<Cut> cut = nextCut(points, volumes, kept.size(), probes, facesMove,
                                           over.grid.cellMeters, gapMeters, refused);
    if (!cut) break;
    const BoxInfluence trimmed = cutBox(std::get<BoxInfluence>(volumes[cut->volume]), *cut);
    const double limit = limits.maxWeightJumpPerCentimeter;
    if (!floorStaysCovered(walked, volumes, cut->volume, trimmed) ||
        !(cut->side == 0
              ? blendStaysSmooth(volumes, cut->volume, trimmed, cut->axis, heights, rows, limit)
              : blendBetterThanWithout(volumes, cut->volume, trimmed, heights, rows, limit))) {
      refused.insert(*cut);
      continue;
    }
    volumes[cut->volume] = trimmed;
    probes[cut->volume - kept.size()].influence = trimmed;
    // The points the trim freed lose the volume; those still over the limit stay.
    std::vector<OverlapPoint> left;
    for (OverlapPoint& p : points) {
      auto it = std::find(p.volumes.begin(), p.volumes.end(), static_cast<int>(cut->volume));
      if (it != p.volumes.end() && !insideInfluence(trimmed, p.pointMeters)) p.volumes.erase(it);
      if (static_cast<int>(p.volumes.size()) > limits.maxOverlap) left.push_back(std::move(p));
    }
    points = std::move(left);
  }
  return points;
}

}  // namespace probeproxy
