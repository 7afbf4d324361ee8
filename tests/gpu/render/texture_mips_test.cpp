// Textures' mip chains made on the CPU (render/texture_mips.h) against closed forms, and against the device's
// own filtering blits (vk/mipmaps.h), which made them before: the same chain within one 8-bit level.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "render/gpu_mesh.h"
#include "render/texture_mips.h"
#include "support/vk_fixture.h"
#include "vk/mipmaps.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

io::Image8 image(uint32_t w, uint32_t h, std::vector<uint8_t> rgba) {
  return {w, h, std::move(rgba)};
}

TEST(TextureMips, LevelsHalveToOneTexelAsTheDeviceCountsThem) {
  EXPECT_EQ(render::mip_count(256, 256), 9u);
  EXPECT_EQ(render::mip_count(5, 3), 3u);  // 5x3, 2x1, 1x1
  EXPECT_EQ(render::mip_count(1, 1), 1u);
  const std::vector<uint8_t> chain = render::rgba8_mip_chain(image(5, 3, std::vector<uint8_t>(60, 7)), true);
  EXPECT_EQ(chain.size(), size_t(4) * (15 + 2 + 1));
  // A flat texture stays flat at every level, in either colour space.
  for (uint8_t v : chain) EXPECT_EQ(v, 7);
}

TEST(TextureMips, EachTexelIsTheMeanOfTheFourAboveInLinearLight) {
  // 2 x 2: black and white in a checkerboard, alpha 0, 255, 255, 0.
  const io::Image8 checker = image(2, 2, {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0});
  const std::vector<uint8_t> linear = render::rgba8_mip_chain(checker, false);
  const std::vector<uint8_t> srgb = render::rgba8_mip_chain(checker, true);
  ASSERT_EQ(linear.size(), 20u);
  ASSERT_EQ(srgb.size(), 20u);
  // Data textures: the mean, 127.5 -> 128.
  EXPECT_EQ(linear[16], 128);
  EXPECT_EQ(linear[19], 128);
  // Colour: half the light, 0.5 linear, is sRGB 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354, 187.5... -> 188 (the
  // mean of the encoded values, 128, would be a fifth too dark); alpha is not encoded.
  const double expected = std::round(255.0 * (1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055));
  EXPECT_EQ(expected, 188.0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(srgb[16 + size_t(c)], expected) << c;
  EXPECT_EQ(srgb[19], 128);
  // 4 x 1 of linear values 0, 100, 200, 40: level 1 is (50, 120), level 2 (85).
  const io::Image8 row = image(4, 1, {0, 0, 0, 0, 100, 100, 100, 100, 200, 200, 200, 200, 40, 40, 40, 40});
  const std::vector<uint8_t> r = render::rgba8_mip_chain(row, false);
  ASSERT_EQ(r.size(), size_t(4) * (4 + 2 + 1));
  EXPECT_EQ(r[16], 50);
  EXPECT_EQ(r[20], 120);
  EXPECT_EQ(r[24], 85);
}

// Power-of-two textures against a reference written here in double: each level the mean of the 2 x 2 texels
// above it, decoded to linear light for colour, rounded to the nearest level.
TEST(TextureMips, RandomTexturesMatchTheBoxFilterInDouble) {
  const auto decode = [](int v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const auto encode = [](double l) {
    return int(std::lround(255.0 * (l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055)));
  };
  for (bool srgb : {true, false}) {
    std::mt19937 rng(srgb ? 3 : 4);
    std::uniform_int_distribution<int> byte(0, 255);
    io::Image8 level0{16, 16, std::vector<uint8_t>(16 * 16 * 4)};
    for (uint8_t& v : level0.rgba) v = uint8_t(byte(rng));
    const std::vector<uint8_t> chain = render::rgba8_mip_chain(level0, srgb);
    std::vector<int> above(level0.rgba.begin(), level0.rgba.end());
    size_t at = above.size(), exact = 0, total = 0;
    for (uint32_t w = 8; w >= 1; w /= 2) {
      std::vector<int> level(size_t(w) * w * 4);
      for (uint32_t y = 0; y < w; ++y)
        for (uint32_t x = 0; x < w; ++x)
          for (uint32_t c = 0; c < 4; ++c) {
            const bool colour = srgb && c < 3;
            double sum = 0;
            int bytes = 0;
            for (uint32_t k = 0; k < 4; ++k) {
              const int v = above[((2 * y + k / 2) * 2 * w + 2 * x + k % 2) * 4 + c];
              sum += decode(v);
              bytes += v;
            }
            // Data: the nearest level to the mean, a tie (x.5) rounded up.
            level[(y * w + x) * 4 + c] = colour ? encode(sum / 4) : (bytes + 2) / 4;
          }
      for (size_t i = 0; i < level.size(); ++i, ++at, ++total) {
        ASSERT_LE(std::abs(int(chain.at(at)) - level[i]), 1)
            << (srgb ? "sRGB" : "UNORM") << " level width " << w;
        exact += int(chain[at]) == level[i];
      }
      above = level;
    }
    EXPECT_EQ(at, chain.size());
    // Data exactly; colour off by one only where the float sum lands across a rounding boundary.
    if (srgb) {
      EXPECT_GE(double(exact), 0.99 * double(total));
    } else {
      EXPECT_EQ(exact, total);
    }
  }
}

class TextureMipsGpu : public GpuTest {};

// upload_texture() puts the CPU's chain in the image's levels, byte for byte; for colour textures it is what
// the device's own linear blits made before within one level. (lavapipe's blits into UNORM truncate: its
// chain darkens by a level or so at each step, 3 levels by 64 x 64's last; the CPU's rounds as a GPU's does.)
TEST_F(TextureMipsGpu, TheUploadedChainIsTheCpusAndColourIsTheDevicesBlitsWithinOneLevel) {
  for (bool srgb : {true, false})
    for (auto [w, h] : {std::pair{64u, 64u}, std::pair{37u, 12u}}) {
      std::mt19937 rng(w * 7 + h + srgb);
      std::uniform_int_distribution<int> byte(0, 255);
      io::Image8 level0{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
      for (uint8_t& v : level0.rgba) v = uint8_t(byte(rng));
      const std::vector<uint8_t> chain = render::rgba8_mip_chain(level0, srgb);
      const vk::Image ours = render::upload_texture(ctx(), level0, "cpu mips", srgb);
      vk::Image blitted =
          vk::Image::create(ctx(), {.format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                                    .extent = {w, h},
                                    .mip_levels = 0,
                                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                             VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    .debug_name = "blitted mips"});
      vk::upload_image(ctx(), blitted, std::as_bytes(std::span(level0.rgba)), VK_IMAGE_LAYOUT_GENERAL,
                       vk::access::kTransferRead);
      ctx().submit_and_wait([&](VkCommandBuffer cmd) {
        vk::generate_mipmaps(cmd, blitted, VK_IMAGE_LAYOUT_GENERAL, vk::access::kTransferWrite,
                             vk::access::kTransferRead);
      });
      ASSERT_EQ(ours.mip_levels(), render::mip_count(w, h));
      ASSERT_EQ(blitted.mip_levels(), ours.mip_levels());
      size_t at = 0;
      for (uint32_t m = 0; m < ours.mip_levels(); ++m) {
        const auto a =
            vk::readback_image(ctx(), ours, VK_IMAGE_LAYOUT_GENERAL, vk::access::kGraphicsSampled, m);
        const auto b =
            vk::readback_image(ctx(), blitted, VK_IMAGE_LAYOUT_GENERAL, vk::access::kTransferRead, m);
        ASSERT_EQ(a.size(), b.size());
        ASSERT_LE(at + a.size(), chain.size());
        int worst = 0;
        for (size_t i = 0; i < a.size(); ++i, ++at) {
          ASSERT_EQ(uint8_t(a[i]), chain[at]) << "level " << m << " byte " << i;
          worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
        }
        if (srgb) {
          EXPECT_LE(worst, 1) << w << "x" << h << " level " << m;
        }
      }
      EXPECT_EQ(at, chain.size());
    }
}

}  // namespace
}  // namespace lagoon::test
