#include "render/texture_mips.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "optics/colour.h"

namespace lagoon::render {
namespace {

// The sRGB transfer functions are optics' (IEC 61966-2-1, in double): decoding through a table of the 256
// values, encoding a texel's colour at once to the nearest 8-bit values.
const std::array<float, 256>& srgb_to_linear() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = float(optics::decode_srgb(glm::dvec3(i / 255.0)).x);
    return t;
  }();
  return table;
}

uint8_t to_byte(double encoded) {
  return uint8_t(std::lround(std::clamp(encoded, 0.0, 1.0) * 255.0));
}

// One level (w x h, four floats a texel) from the level above (sw x sh).
std::vector<float> halve(const std::vector<float>& src, uint32_t sw, uint32_t sh, uint32_t w, uint32_t h) {
  std::vector<float> out(size_t(w) * h * 4);
  // Where each destination texel's centre falls in the source, in texel units: its two taps and the second's
  // weight.
  struct Tap {
    uint32_t a, b;
    float wb;
  };
  auto taps = [](uint32_t n_src, uint32_t n_dst) {
    std::vector<Tap> t(n_dst);
    for (uint32_t x = 0; x < n_dst; ++x) {
      const double u = std::max(0.0, (x + 0.5) * double(n_src) / double(n_dst) - 0.5);
      const uint32_t a = std::min(uint32_t(u), n_src - 1);
      t[x] = {a, std::min(a + 1, n_src - 1), float(u - a)};
    }
    return t;
  };
  const std::vector<Tap> tx = taps(sw, w), ty = taps(sh, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (size_t c = 0; c < 4; ++c) {
        const auto at = [&](uint32_t i, uint32_t j) { return src[(size_t(j) * sw + i) * 4 + c]; };
        const float top = at(tx[x].a, ty[y].a) + tx[x].wb * (at(tx[x].b, ty[y].a) - at(tx[x].a, ty[y].a));
        const float bottom = at(tx[x].a, ty[y].b) + tx[x].wb * (at(tx[x].b, ty[y].b) - at(tx[x].a, ty[y].b));
        out[(size_t(y) * w + x) * 4 + c] = top + ty[y].wb * (bottom - top);
      }
  return out;
}

}  // namespace

uint32_t mip_count(uint32_t width, uint32_t height) {
  return uint32_t(std::bit_width(std::max(width, height)));
}

std::vector<uint8_t> rgba8_mip_chain(const io::Image8& image, bool srgb) {
  std::vector<uint8_t> chain(image.rgba.begin(), image.rgba.end());
  const uint32_t levels = mip_count(image.width, image.height);
  if (levels <= 1) return chain;
  // Level 0 as floats: colour in linear light; data (and alpha, linear in either format) in 8-bit units, in
  // which the mean of 2 x 2 texels is exact, so a tie (x.5) always rounds up.
  const auto colour = [srgb](size_t i) { return srgb && i % 4 != 3; };
  std::vector<float> level(image.rgba.size());
  for (size_t i = 0; i < level.size(); ++i)
    level[i] = colour(i) ? srgb_to_linear()[image.rgba[i]] : float(image.rgba[i]);
  uint32_t w = image.width, h = image.height;
  for (uint32_t m = 1; m < levels; ++m) {
    const uint32_t nw = std::max(1u, w >> 1), nh = std::max(1u, h >> 1);
    level = halve(level, w, h, nw, nh);
    w = nw, h = nh;
    // Each level is rounded to 8 bits as a blit stores it, and the next is made from the stored values.
    for (size_t t = 0; t < level.size(); t += 4) {
      const glm::dvec3 encoded =
          srgb ? optics::encode_srgb(glm::dvec3(level[t], level[t + 1], level[t + 2])) : glm::dvec3(0.0);
      for (size_t i = t; i < t + 4; ++i) {
        const uint8_t byte = colour(i) ? to_byte(encoded[int(i - t)])
                                       : uint8_t(std::lround(std::clamp(level[i], 0.0f, 255.0f)));
        chain.push_back(byte);
        level[i] = colour(i) ? srgb_to_linear()[byte] : float(byte);
      }
    }
  }
  return chain;
}

}  // namespace lagoon::render
