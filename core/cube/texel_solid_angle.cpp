#include "core/cube/texel_solid_angle.h"

#include <cmath>

namespace probeproxy {

namespace {

double cornerArea(double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0)); }

}  // namespace

double texelSolidAngle(int col, int row, int faceSize) {
  const double step = 2.0 / faceSize;
  const double x0 = -1.0 + col * step, x1 = x0 + step;
  const double y0 = -1.0 + row * step, y1 = y0 + step;
  return cornerArea(x1, y1) - cornerArea(x0, y1) - cornerArea(x1, y0) + cornerArea(x0, y0);
}

}  // namespace probeproxy
