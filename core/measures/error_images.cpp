#include "core/measures/error_images.h"

#include "core/image/rgb8_canvas.h"
#include "core/image/write_png.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace probeproxy {

namespace {

using Rgb8 = std::array<std::uint8_t, 3>;

constexpr int kMinPanelPixels = 256;  // each panel's shorter side, at least
constexpr int kMargin = 12, kTitleHeight = 32, kLegendWidth = 230, kLegendHeight = 330;
constexpr Rgb8 kOutsideMask{40, 40, 40};
constexpr Rgb8 kMissCyan{0, 255, 255};

float linearToSrgb(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

Rgb8 heat(float t) {
  // Stops at 0, 1/3, 2/3, 1: black, red, yellow, white.
  const float s = std::clamp(t, 0.0f, 1.0f) * 3.0f;
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return {byte(s), byte(s - 1.0f), byte(s - 2.0f)};
}

// The error scale as a bar, 0 at the bottom, scaleMax and above at the top, with its stops
// labelled; then the swatches for a miss and for pixels outside the mirror.
void drawErrorLegend(Rgb8Canvas& canvas, int left, float scaleMax, float peak) {
  constexpr int kBarHeight = 180, kBarTop = kTitleHeight + 26;
  drawText(canvas, left, 8, "|error|, radiance", 2, 0, 0, 0);
  for (int y = 0; y < kBarHeight; ++y) {
    const Rgb8 c = heat(1.0f - float(y) / float(kBarHeight - 1));
    canvas.fill(left, kBarTop + y, 28, 1, c[0], c[1], c[2]);
  }
  for (int stop = 0; stop <= 3; ++stop) {
    const int y = kBarTop + (kBarHeight - 1) * (3 - stop) / 3;
    canvas.fill(left + 28, y, 6, 1, 0, 0, 0);
    drawText(canvas, left + 40, y - 6, number(scaleMax * stop / 3.0) + (stop == 3 ? "+" : ""), 2, 0,
             0, 0);
  }
  int y = kBarTop + kBarHeight + 16;
  canvas.fill(left, y, 28, 18, kMissCyan[0], kMissCyan[1], kMissCyan[2]);
  drawText(canvas, left + 36, y + 2, "miss", 2, 0, 0, 0);
  y += 26;
  canvas.fill(left, y, 28, 18, kOutsideMask[0], kOutsideMask[1], kOutsideMask[2]);
  drawText(canvas, left + 36, y + 2, "not mirror", 2, 0, 0, 0);
  y += 30;
  drawText(canvas, left, y, "white at " + number(peak), 2, 0, 0, 0);
}

void checkSizes(int width, int height, std::size_t mask, std::size_t miss) {
  const std::size_t n = static_cast<std::size_t>(std::max(width, 0)) * std::max(height, 0);
  if (mask != n || miss != n) {
    throw std::invalid_argument("error images: mask or miss mask does not match the image size");
  }
}

}  // namespace

void writeErrorComparisonPng(const std::filesystem::path& file, const ErrorComparison& images) {
  const int w = images.width, h = images.height;
  checkSizes(w, h, images.mask.size(), images.miss.size());
  const std::size_t n = images.mask.size();
  if (images.absError.size() != n || images.referenceRgb.size() != 3 * n ||
      images.reconstructionRgb.size() != 3 * n || !(images.scaleMax > 0.0f) ||
      !(images.peak > 0.0f)) {
    throw std::invalid_argument("writeErrorComparisonPng: wrong image sizes or non-positive scale");
  }
  const int zoom = std::max(1, (kMinPanelPixels + std::min(w, h) - 1) / std::min(w, h));
  const int panelW = w * zoom, panelH = h * zoom;
  Rgb8Canvas canvas;
  canvas.width = kMargin + 3 * (panelW + kMargin) + kLegendWidth;
  canvas.height = std::max(kTitleHeight + panelH + kMargin, kTitleHeight + kLegendHeight);
  canvas.rgb8.assign(static_cast<std::size_t>(canvas.width) * canvas.height * 3, 255);

  const auto exposed = [&](std::span<const float> rgb, std::size_t i) {
    const auto byte = [&](float v) {
      const float encoded = linearToSrgb(std::clamp(v / images.peak, 0.0f, 1.0f));
      return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
    };
    return Rgb8{byte(rgb[3 * i]), byte(rgb[3 * i + 1]), byte(rgb[3 * i + 2])};
  };
  const std::array<const char*, 3> titles = {"cycles reference", "reconstruction", "|error|"};
  for (int panel = 0; panel < 3; ++panel) {
    const int left = kMargin + panel * (panelW + kMargin);
    drawText(canvas, left, 8, titles[panel], 2, 0, 0, 0);
    for (int row = 0; row < h; ++row) {
      for (int col = 0; col < w; ++col) {
        const std::size_t i = static_cast<std::size_t>(row) * w + col;
        const bool inside = images.mask[i] != 0, missed = images.miss[i] != 0;
        const Rgb8 c = panel == 0   ? exposed(images.referenceRgb, i)
                       : !inside    ? kOutsideMask
                       : missed     ? kMissCyan
                       : panel == 1 ? exposed(images.reconstructionRgb, i)
                                    : heat(images.absError[i] / images.scaleMax);
        canvas.fill(left + col * zoom, kTitleHeight + row * zoom, zoom, zoom, c[0], c[1], c[2]);
      }
    }
  }
  drawErrorLegend(canvas, canvas.width - kLegendWidth + 8, images.scaleMax, images.peak);
  writePng(file, canvas.width, canvas.height, canvas.rgb8);
}

void writeMissMaskPng(const std::filesystem::path& file, int width, int height,
                      std::span<const std::uint8_t> mask, std::span<const std::uint8_t> miss) {
  checkSizes(width, height, mask.size(), miss.size());
  std::vector<std::uint8_t> rgb(mask.size() * 3);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const Rgb8 c = !mask[i] ? Rgb8{0, 0, 0} : miss[i] ? Rgb8{255, 0, 0} : Rgb8{255, 255, 255};
    std::copy(c.begin(), c.end(), rgb.begin() + static_cast<std::ptrdiff_t>(i * 3));
  }
  writePng(file, width, height, rgb);
}

}  // namespace probeproxy
