// Labels drawn into 8-bit images (contact sheets, plots): stb_easy_font's quads (Debian's libstb-dev)
// filled pixel by pixel, scaled by a whole number. Plain ASCII; other bytes draw nothing.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "io/png.h"

namespace lagoon::io {

using Rgb8 = std::array<uint8_t, 3>;

// The colours every chart Lagoon draws shares (plots, contact sheets, previews): one look.
namespace chart {
inline constexpr Rgb8 kBackground{24, 28, 36};
inline constexpr Rgb8 kAxis{120, 130, 140};
inline constexpr Rgb8 kText{220, 225, 230};
inline constexpr Rgb8 kDim{140, 150, 160};
}  // namespace chart

// Fills the rectangle [x, x + w) x [y, y + h), clipped to the image.
void fill_rect(Image8& image, int x, int y, int w, int h, Rgb8 colour);

// A line two pixels wide from (xa, ya) to (xb, yb), clipped to the image.
void draw_line(Image8& image, int xa, int ya, int xb, int yb, Rgb8 colour);

// Draws `text` with its top-left corner at (x, y), each font pixel `scale` image pixels wide; '\n' starts a
// new line. Returns the drawn width in pixels.
int draw_text(Image8& image, int x, int y, std::string_view text, Rgb8 colour, int scale = 1);

// The width and height `text` would take.
std::array<int, 2> text_size(std::string_view text, int scale = 1);

}  // namespace lagoon::io
