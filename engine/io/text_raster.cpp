#include "io/text_raster.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace lagoon::io {
namespace {

// stb_easy_font's vertex: x, y, z, then 4 colour bytes; 4 vertices per quad.
struct FontVertex {
  float x, y, z;
  uint8_t colour[4];
};

std::vector<FontVertex> quads(std::string_view text) {
  std::string copy(text);
  // About 270 bytes of vertices per character at most (stb_easy_font's documentation).
  std::vector<FontVertex> buffer((copy.size() + 1) * 300 / sizeof(FontVertex) * 4);
  const int count =
      stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size() * sizeof(FontVertex)));
  buffer.resize(size_t(count) * 4);
  return buffer;
}

}  // namespace

void draw_line(Image8& image, int xa, int ya, int xb, int yb, Rgb8 colour) {
  const int steps = std::max({std::abs(xb - xa), std::abs(yb - ya), 1});
  for (int s = 0; s <= steps; ++s)
    fill_rect(image, xa + (xb - xa) * s / steps, ya + (yb - ya) * s / steps, 2, 2, colour);
}

void fill_rect(Image8& image, int x, int y, int w, int h, Rgb8 colour) {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + w, int(image.width)), y1 = std::min(y + h, int(image.height));
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) {
      uint8_t* p = image.pixel(uint32_t(i), uint32_t(j));
      p[0] = colour[0], p[1] = colour[1], p[2] = colour[2], p[3] = 255;
    }
}

int draw_text(Image8& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  const std::vector<FontVertex> v = quads(text);
  for (size_t q = 0; q + 3 < v.size(); q += 4) {  // axis-aligned: corners 0 and 2 are opposite
    const int qx = int(std::min(v[q].x, v[q + 2].x)), qy = int(std::min(v[q].y, v[q + 2].y));
    const int qw = int(std::abs(v[q + 2].x - v[q].x)), qh = int(std::abs(v[q + 2].y - v[q].y));
    fill_rect(image, x + qx * scale, y + qy * scale, qw * scale, qh * scale, colour);
  }
  return text_size(text, scale)[0];
}

std::array<int, 2> text_size(std::string_view text, int scale) {
  std::string copy(text);
  return {stb_easy_font_width(copy.data()) * scale, stb_easy_font_height(copy.data()) * scale};
}

}  // namespace lagoon::io
