#pragma once
// Pictures with legends (the survey's maps, bench's mirror-view comparisons) drawn without a
// font library: an RGB canvas and a fixed 5x7 bitmap font of the digits, a few signs and the
// letters, upper case drawn as lower case. Characters it lacks are drawn as blanks.

#include <cstdint>
#include <string_view>
#include <vector>

namespace probeproxy {

struct Rgb8Canvas {  // row 0 at the top; owns its pixels
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb8;  // (row * width + col) * 3 + channel

  void set(int col, int row, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (col < 0 || row < 0 || col >= width || row >= height) return;
    const std::size_t i = (static_cast<std::size_t>(row) * width + col) * 3;
    rgb8[i] = r, rgb8[i + 1] = g, rgb8[i + 2] = b;
  }
  void fill(int col, int row, int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    for (int y = row; y < row + h; ++y)
      for (int x = col; x < col + w; ++x) set(x, y, r, g, b);
  }
};

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7;

// Draws `text` with its top-left corner at (col, row), each font pixel `scale` pixels square,
// one font pixel between characters. Returns the column after the last character.
int drawText(Rgb8Canvas& canvas, int col, int row, std::string_view text, int scale, std::uint8_t r,
             std::uint8_t g, std::uint8_t b);

}  // namespace probeproxy
