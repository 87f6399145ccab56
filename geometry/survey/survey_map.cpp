#include "geometry/survey/survey_map.h"

#include "core/blend/weight_picture.h"
#include "core/image/scale_bar.h"
#include "core/image/write_png.h"
#include "geometry/survey/storeys.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace probeproxy {

namespace {

constexpr int kLongSidePixels = 1000;  // the floor's longer side
constexpr int kMinMapWidth = 640;      // plus the legend: at least 800 wide in all
constexpr int kMaxMapPixels = 4000;
constexpr int kLegendWidth = 200;
constexpr double kMarginMeters = 1.0;
constexpr std::uint8_t kNoFloor = 40;
constexpr std::uint8_t kOccludedGrey = 120;

// Green (exact) through yellow and red to purple (useless): one colour per bin.
constexpr std::array<std::array<std::uint8_t, 3>, kSurveyScaleDeg.size()> kBinColours = {{
    {20, 110, 50},
    {90, 180, 70},
    {180, 220, 80},
    {250, 220, 60},
    {245, 150, 40},
    {225, 60, 35},
    {160, 20, 80},
    {90, 0, 110},
}};

std::string degreeLabel(double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", deg);
  return text;
}

struct MapFrame {  // world x, y -> pixel
  glm::dvec2 minMeters{0.0};
  double pixelsPerMeter = 1.0;
  int width = 0, height = 0;

  glm::dvec2 world(int col, int row) const {
    return {minMeters.x + (col + 0.5) / pixelsPerMeter,
            minMeters.y + (height - row - 0.5) / pixelsPerMeter};
  }
  int column(double x) const {
    return static_cast<int>(std::floor((x - minMeters.x) * pixelsPerMeter));
  }
  int row(double y) const {
    return height - 1 - static_cast<int>(std::floor((y - minMeters.y) * pixelsPerMeter));
  }
};

// The floor and every outer range over it, whole: an outline cut by the picture's edge reads
// as a volume that stops there.
MapFrame mapFrame(const WalkableFloor& floor, std::span<const Probe> probes) {
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const FloorCell& c : floor.cells) {
    lo = glm::min(lo, glm::dvec2(c.pointMeters) - 0.5 * floor.spacingMeters);
    hi = glm::max(hi, glm::dvec2(c.pointMeters) + 0.5 * floor.spacingMeters);
  }
  if (floor.cells.empty()) lo = hi = glm::dvec2(0.0);
  for (const Probe& p : probes) {
    glm::dvec3 volumeLo, volumeHi;
    influenceBounds(p.influence, volumeLo, volumeHi);
    lo = glm::min(lo, glm::dvec2(volumeLo));
    hi = glm::max(hi, glm::dvec2(volumeHi));
  }
  lo -= kMarginMeters;
  hi += kMarginMeters;
  const glm::dvec2 extent = hi - lo;
  MapFrame f;
  f.minMeters = lo;
  f.pixelsPerMeter = kLongSidePixels / std::max(extent.x, extent.y);
  f.pixelsPerMeter = std::max(f.pixelsPerMeter, kMinMapWidth / extent.x);
  f.pixelsPerMeter = std::min(f.pixelsPerMeter, kMaxMapPixels / std::max(extent.x, extent.y));
  f.width = std::max(1, static_cast<int>(std::ceil(extent.x * f.pixelsPerMeter)));
  f.height = std::max(1, static_cast<int>(std::ceil(extent.y * f.pixelsPerMeter)));
  return f;
}

void drawHatch(Rgb8Canvas& canvas, int col, int row, int w, int h) {
  for (int y = row; y < row + h; ++y)
    for (int x = col; x < col + w; ++x) {
      // Diagonal stripes fixed to the picture, so neighbouring cells join up.
      const bool stripe = ((x + y) % 8) < 2;
      const std::uint8_t v = stripe ? 30 : 215;
      canvas.set(x, y, v, v, v);
    }
}

void drawCells(Rgb8Canvas& canvas, const MapFrame& f, const SurveyResult& r,
               std::span<const int> storeyOf, int storey) {
  const double half = 0.5 * r.floor.spacingMeters;
  for (std::size_t i = 0; i < r.floor.cells.size(); ++i) {
    if (storeyOf[i] != storey) continue;
    const FloorCell& c = r.floor.cells[i];
    const int c0 = f.column(c.pointMeters.x - half), c1 = f.column(c.pointMeters.x + half);
    const int r0 = f.row(c.pointMeters.y + half), r1 = f.row(c.pointMeters.y - half);
    // Half-open pixel spans, so neighbouring cells neither overlap nor leave gaps.
    const int w = std::max(1, c1 - c0), h = std::max(1, r1 - r0);
    const SurveyCellError& e = r.cells[i];
    if (e.uncoveredShare > 0.5) {
      drawHatch(canvas, c0, r0, w, h);
    } else if (std::isnan(e.medianDeg)) {
      canvas.fill(c0, r0, w, h, kOccludedGrey, kOccludedGrey, kOccludedGrey);
    } else {
      const auto rgb = surveyErrorColour(e.medianDeg);
      canvas.fill(c0, r0, w, h, rgb[0], rgb[1], rgb[2]);
    }
  }
}

// Each volume's outer range sliced a metre above the storey's floor, outlined in its colour.
void drawInfluences(Rgb8Canvas& canvas, const MapFrame& f, std::span<const Probe> probes,
                    double sliceZ) {
  std::vector<char> inside(static_cast<std::size_t>(f.width) * f.height, 0);
  for (std::size_t p = 0; p < probes.size(); ++p) {
    // Only the pixels of the volume's bounds, a pixel wider: outside them nothing is inside,
    // so no outline (a level's hundred probes would otherwise each scan the whole map).
    glm::dvec3 lo, hi;
    influenceBounds(probes[p].influence, lo, hi);
    const int col0 = std::clamp(f.column(lo.x) - 1, 0, f.width - 1);
    const int col1 = std::clamp(f.column(hi.x) + 1, 0, f.width - 1);
    const int row0 = std::clamp(f.row(hi.y) - 1, 0, f.height - 1);
    const int row1 = std::clamp(f.row(lo.y) + 1, 0, f.height - 1);
    for (int row = row0; row <= row1; ++row)
      for (int col = col0; col <= col1; ++col) {
        const glm::dvec2 xy = f.world(col, row);
        inside[static_cast<std::size_t>(row) * f.width + col] =
            insideInfluence(probes[p].influence, {xy.x, xy.y, sliceZ});
      }
    const glm::u8vec3 colour = probeColour(static_cast<int>(p));
    for (int row = row0; row <= row1; ++row)
      for (int col = col0; col <= col1; ++col) {
        const std::size_t i = static_cast<std::size_t>(row) * f.width + col;
        const bool edge = (col + 1 < f.width && inside[i] != inside[i + 1]) ||
                          (row + 1 < f.height && inside[i] != inside[i + f.width]);
        if (edge) {
          canvas.fill(col, row, 2, 2, colour.r, colour.g, colour.b);
        }
      }
    for (int row = row0; row <= row1; ++row)
      std::fill_n(inside.begin() + static_cast<std::ptrdiff_t>(row) * f.width + col0,
                  col1 - col0 + 1, 0);
  }
}

void drawMarker(Rgb8Canvas& canvas, int col, int row) {
  canvas.fill(col - 4, row - 4, 9, 9, 255, 255, 255);
  canvas.fill(col - 2, row - 2, 5, 5, 0, 0, 0);
}

void drawLegend(Rgb8Canvas& canvas, int left, int storey, int storeys) {
  canvas.fill(left, 0, kLegendWidth, canvas.height, 255, 255, 255);
  const int x = left + 12;
  int y = 12;
  drawText(canvas, x, y, "error, deg", 2, 0, 0, 0);
  y += 18;
  drawText(canvas, x, y, "median of each cell", 1, 0, 0, 0);
  y += 16;
  for (std::size_t k = kSurveyScaleDeg.size(); k-- > 0;) {
    const auto& c = kBinColours[k];
    canvas.fill(x, y, 28, 18, c[0], c[1], c[2]);
    const std::string label =
        k + 1 < kSurveyScaleDeg.size()
            ? degreeLabel(kSurveyScaleDeg[k]) + "-" + degreeLabel(kSurveyScaleDeg[k + 1])
            : degreeLabel(kSurveyScaleDeg[k]) + "+";
    drawText(canvas, x + 36, y + 2, label, 2, 0, 0, 0);
    y += 24;
  }
  y += 10;
  drawHatch(canvas, x, y, 28, 18);
  drawText(canvas, x + 36, y + 2, "uncovered", 2, 0, 0, 0);
  y += 24;
  canvas.fill(x, y, 28, 18, kOccludedGrey, kOccludedGrey, kOccludedGrey);
  drawText(canvas, x + 36, y + 2, "occluded", 2, 0, 0, 0);
  y += 24;
  canvas.fill(x, y, 28, 18, kNoFloor, kNoFloor, kNoFloor);
  drawText(canvas, x + 36, y + 2, "no floor", 2, 0, 0, 0);
  y += 24;
  canvas.fill(x, y, 28, 18, 255, 255, 255);
  drawMarker(canvas, x + 14, y + 9);
  drawText(canvas, x + 36, y + 2, "capture", 2, 0, 0, 0);
  y += 24;
  canvas.fill(x, y + 8, 28, 2, 255, 0, 0);
  drawText(canvas, x + 36, y + 2, "influence", 2, 0, 0, 0);
  y += 34;
  if (storeys > 1)
    drawText(canvas, x, y, "storey " + std::to_string(storey + 1) + "/" + std::to_string(storeys),
             2, 0, 0, 0);
}

}  // namespace

std::array<std::uint8_t, 3> surveyErrorColour(double errorDeg) {
  std::size_t bin = 0;
  while (bin + 1 < kSurveyScaleDeg.size() && errorDeg >= kSurveyScaleDeg[bin + 1]) ++bin;
  return kBinColours[bin];
}

Rgb8Canvas renderSurveyMap(const SurveyResult& r, std::span<const Probe> probes,
                           std::span<const int> storeyOf, int storey, int storeyCount,
                           const SurveyMapOptions& options) {
  const MapFrame f = mapFrame(r.floor, probes);
  Rgb8Canvas canvas;
  canvas.width = f.width + kLegendWidth;
  canvas.height = std::max(f.height, 420);
  canvas.rgb8.assign(static_cast<std::size_t>(canvas.width) * canvas.height * 3, kNoFloor);
  drawCells(canvas, f, r, storeyOf, storey);

  // The storey's floor height: its lowest cell, so outlines and markers belong to it.
  double floorZ = std::numeric_limits<double>::infinity(), topZ = -floorZ;
  for (std::size_t i = 0; i < r.floor.cells.size(); ++i)
    if (storeyOf[i] == storey) {
      floorZ = std::min(floorZ, r.floor.cells[i].pointMeters.z);
      topZ = std::max(topZ, r.floor.cells[i].pointMeters.z);
    }
  if (!std::isfinite(floorZ)) floorZ = topZ = 0.0;
  drawInfluences(canvas, f, probes, floorZ + 1.0);
  for (const Probe& p : probes) {
    // On a storey's map, the probes standing over it (one storey: all of them).
    const bool here =
        storeyCount == 1 || (p.captureMeters.z >= floorZ - 0.5 && p.captureMeters.z <= topZ + 3.0);
    if (!here) continue;
    const int col = f.column(p.captureMeters.x), row = f.row(p.captureMeters.y);
    drawMarker(canvas, col, row);
    if (options.probeNames) {
      // Black on a white ground beside the marker, so a name reads on any floor colour.
      const int width = static_cast<int>(p.name.size()) * (kGlyphWidth + 1) + 3;
      canvas.fill(col + 6, row - 5, width, kGlyphHeight + 3, 255, 255, 255);
      drawText(canvas, col + 8, row - 3, p.name, 1, 0, 0, 0);
    }
  }
  drawScaleBar(canvas, f.width, f.height, f.pixelsPerMeter);
  drawLegend(canvas, f.width, storey, storeyCount);
  return canvas;
}

std::vector<std::filesystem::path> writeSurveyMaps(const SurveyResult& r,
                                                   std::span<const Probe> probes,
                                                   const std::filesystem::path& outFolder,
                                                   const SurveyMapOptions& options) {
  const std::vector<int> storeyOf = floorStoreys(r.floor);
  const int storeys =
      storeyOf.empty() ? 1 : *std::max_element(storeyOf.begin(), storeyOf.end()) + 1;
  std::vector<std::filesystem::path> files;
  for (int s = 0; s < storeys; ++s) {
    const Rgb8Canvas map = renderSurveyMap(r, probes, storeyOf, s, storeys, options);
    const std::string name = storeys == 1
                                 ? r.scene + "_survey.png"
                                 : r.scene + "_survey_storey" + std::to_string(s + 1) + ".png";
    files.push_back(outFolder / name);
    writePng(files.back(), map.width, map.height, map.rgb8);
  }
  return files;
}

}  // namespace probeproxy
