#include "core/image/scale_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace probeproxy {

void drawScaleBar(Rgb8Canvas& canvas, int mapWidth, int mapHeight, double pixelsPerMeter) {
  const double target = 0.2 * mapWidth / pixelsPerMeter;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  double meters = decade;
  for (double multiple : {2.0, 5.0})
    if (multiple * decade <= target) meters = multiple * decade;
  const int bar = std::max(1, static_cast<int>(std::lround(meters * pixelsPerMeter)));
  const int x = 12, y = mapHeight - 40;
  canvas.fill(x - 6, y - 6, bar + 12, 36, 255, 255, 255);
  canvas.fill(x, y, bar, 6, 0, 0, 0);
  canvas.fill(x, y - 4, 2, 10, 0, 0, 0);
  canvas.fill(x + bar - 2, y - 4, 2, 10, 0, 0, 0);
  char label[32];
  std::snprintf(label, sizeof label, "%g m", meters);
  drawText(canvas, x, y + 10, label, 2, 0, 0, 0);
}

}  // namespace probeproxy
