#pragma once
// A map's scale: a bar of a round length (1, 2 or 5 times a power of ten) near a fifth of the
// map's width, in its lower left corner on a white ground, so it reads against any colour.

#include "core/image/rgb8_canvas.h"

namespace probeproxy {

// The map is the canvas's columns [0, mapWidth) and rows [0, mapHeight).
void drawScaleBar(Rgb8Canvas& canvas, int mapWidth, int mapHeight, double pixelsPerMeter);

}  // namespace probeproxy
