#include "core/blend/weight_picture_legend.h"

#include "core/image/scale_bar.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace probeproxy {

namespace {

constexpr int kItemWidth = 220;  // a swatch and a label at twice the font's size
constexpr int kItemHeight = 24;
constexpr int kMargin = 12;
constexpr int kTitleHeight = 26;
constexpr int kScaleBarHeight = 48;  // core/image/scale_bar.h draws 40 up from its bottom
constexpr std::size_t kLabelChars = (kItemWidth - 40) / ((kGlyphWidth + 1) * 2);

using Swatch = std::function<void(Rgb8Canvas&, int col, int row)>;

struct Item {
  Swatch swatch;
  std::string label;
};

std::string fitted(const std::string& label) {
  return label.size() <= kLabelChars ? label : label.substr(0, kLabelChars - 2) + "..";
}

void swatchOf(Rgb8Canvas& c, int col, int row, glm::u8vec3 fill) {
  c.fill(col, row, 28, 18, fill.r, fill.g, fill.b);
}

}  // namespace

Rgb8Canvas weightPictureWithLegend(const WeightPicture& picture,
                                   std::span<const std::string> probeNames,
                                   std::string_view title) {
  std::vector<Item> items;
  for (std::size_t i = 0; i < probeNames.size(); ++i) {
    const glm::u8vec3 colour = probeColour(static_cast<int>(i));
    items.push_back({[colour](Rgb8Canvas& c, int col, int row) { swatchOf(c, col, row, colour); },
                     fitted(probeNames[i])});
  }
  // The outlines as the picture draws them: a line between two pixels that differ.
  items.push_back({[](Rgb8Canvas& c, int col, int row) {
                     swatchOf(c, col, row, {0, 0, 0});
                     c.fill(col + 13, row, 1, 18, 255, 255, 255);
                   },
                   "influence edge"});
  items.push_back({[](Rgb8Canvas& c, int col, int row) {
                     swatchOf(c, col, row, {0, 0, 0});
                     c.fill(col + 13, row, 1, 18, 128, 128, 128);
                   },
                   "inner range"});
  items.push_back({[](Rgb8Canvas& c, int col, int row) {
                     swatchOf(c, col, row, {0, 0, 0});
                     c.fill(col + 11, row + 6, 7, 7, 255, 255, 255);
                     c.fill(col + 13, row + 8, 3, 3, 0, 0, 0);
                   },
                   "capture point"});
  items.push_back({[](Rgb8Canvas& c, int col, int row) {
                     swatchOf(c, col, row, {0, 0, 0});
                   },
                   "no probe"});

  const int perRow = std::max(1, (picture.width - kMargin) / kItemWidth);
  const int itemRows = (static_cast<int>(items.size()) + perRow - 1) / perRow;
  const int legendTop = picture.height;
  const int legendHeight = kMargin + kTitleHeight + itemRows * kItemHeight + kScaleBarHeight;
  Rgb8Canvas canvas;
  canvas.width = std::max(picture.width, kItemWidth + kMargin);
  canvas.height = picture.height + legendHeight;
  canvas.rgb8.assign(static_cast<std::size_t>(canvas.width) * canvas.height * 3, 255);
  for (int row = 0; row < picture.height; ++row)
    std::copy_n(picture.rgb8.begin() + static_cast<std::ptrdiff_t>(row) * picture.width * 3,
                picture.width * 3,
                canvas.rgb8.begin() + static_cast<std::ptrdiff_t>(row) * canvas.width * 3);
  drawText(canvas, kMargin, legendTop + kMargin, title, 2, 0, 0, 0);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const int col = kMargin + static_cast<int>(i % perRow) * kItemWidth;
    const int row = legendTop + kMargin + kTitleHeight + static_cast<int>(i / perRow) * kItemHeight;
    items[i].swatch(canvas, col, row);
    drawText(canvas, col + 36, row + 2, items[i].label, 2, 0, 0, 0);
  }
  drawScaleBar(canvas, picture.width, canvas.height, 1.0 / picture.metersPerPixel);
  return canvas;
}

Rgb8Canvas sceneWeightPicture(const Scene& scene, double zMeters, const BlendOptions& options) {
  std::vector<InfluenceVolume> volumes;
  std::vector<glm::dvec3> captures;
  std::vector<std::string> names;
  for (const Probe& p : scene.probes) {
    volumes.push_back(p.influence);
    captures.push_back(p.captureMeters);
    names.push_back(p.name);
  }
  char title[96];
  std::snprintf(title, sizeof title, "blend weights at z = %.2f m, %s", zMeters,
                std::string(blendSchemeName(options.scheme)).c_str());
  return weightPictureWithLegend(renderWeightPicture(volumes, zMeters, options, 800, captures),
                                 names, title);
}

}  // namespace probeproxy
