// Images decoded by libpng, libjpeg-turbo and libwebp (engine/io/image_decode.h), checked against pixels the
// test made itself and encoded with independent encoders (stb_image_write for PNG and JPEG, libwebp's encoder
// for WebP); hostile inputs found by fuzzing stb_image stay refused with the library's reason.
#include "io/image_decode.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <webp/encode.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/png.h"
#include "support/temp_dir.h"

namespace lagoon::io {
namespace {

std::vector<uint8_t> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
}

// A smooth RGBA test card: red across, green down, blue and alpha from both, so a swapped channel, a
// flipped row order or a wrong stride all show.
std::vector<uint8_t> test_card(int w, int h) {
  std::vector<uint8_t> rgba(size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &rgba[(size_t(y) * w + x) * 4];
      p[0] = uint8_t(255 * x / (w - 1));
      p[1] = uint8_t(255 * y / (h - 1));
      p[2] = uint8_t(128 + 100 * (x - y) / (w + h));
      p[3] = uint8_t(255 - 200 * (x + y) / (w + h));
    }
  return rgba;
}

std::vector<uint8_t> opaque(std::vector<uint8_t> rgba) {
  for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  return rgba;
}

// An opaque card of w x h as PNG, JPEG (quality 90) and lossless WebP, each by its independent encoder.
std::vector<std::vector<uint8_t>> in_every_format(int w, int h) {
  const std::vector<uint8_t> card = opaque(test_card(w, h));
  std::vector<uint8_t> png, jpeg;
  stbi_write_png_to_func(append_bytes, &png, w, h, 4, card.data(), w * 4);
  stbi_write_jpg_to_func(append_bytes, &jpeg, w, h, 4, card.data(), 90);
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(card.data(), w, h, w * 4, &encoded);
  std::vector<uint8_t> webp(encoded, encoded + size);
  WebPFree(encoded);
  return {png, jpeg, webp};
}

// Largest and mean absolute difference over the colour channels.
std::pair<int, double> difference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  int largest = 0;
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (i % 4 == 3) continue;
    const int d = std::abs(int(a[i]) - int(b[i]));
    largest = std::max(largest, d);
    sum += d;
    ++n;
  }
  return {largest, n ? sum / double(n) : 0.0};
}

TEST(ImageDecode, PngRoundTripsExactlyWithAlpha) {
  const int w = 37, h = 19;  // odd sizes: rows are not padded
  const std::vector<uint8_t> card = test_card(w, h);
  std::vector<uint8_t> png;
  ASSERT_NE(stbi_write_png_to_func(append_bytes, &png, w, h, 4, card.data(), w * 4), 0);
  auto image = decode_image(png, "card.png", 1024);
  ASSERT_TRUE(image.ok()) << image.error().message;
  EXPECT_EQ(image->width, uint32_t(w));
  EXPECT_EQ(image->height, uint32_t(h));
  EXPECT_EQ(image->rgba, card);
}

TEST(ImageDecode, GreyAndRgbPngsComeBackAsOpaqueRgba) {
  const int w = 5, h = 3;
  std::vector<uint8_t> grey(w * h), rgb(w * h * 3);
  for (int i = 0; i < w * h; ++i) {
    grey[i] = uint8_t(i * 17);
    rgb[i * 3] = uint8_t(i * 3), rgb[i * 3 + 1] = uint8_t(200 - i), rgb[i * 3 + 2] = uint8_t(i * 11);
  }
  std::vector<uint8_t> grey_png, rgb_png;
  ASSERT_NE(stbi_write_png_to_func(append_bytes, &grey_png, w, h, 1, grey.data(), w), 0);
  ASSERT_NE(stbi_write_png_to_func(append_bytes, &rgb_png, w, h, 3, rgb.data(), w * 3), 0);
  auto g = decode_png(grey_png, "grey.png", 64);
  auto c = decode_png(rgb_png, "rgb.png", 64);
  ASSERT_TRUE(g.ok() && c.ok());
  for (int i = 0; i < w * h; ++i) {
    EXPECT_EQ(g->rgba[i * 4 + 0], grey[i]);
    EXPECT_EQ(g->rgba[i * 4 + 2], grey[i]);
    EXPECT_EQ(g->rgba[i * 4 + 3], 255);
    EXPECT_EQ(c->rgba[i * 4 + 1], rgb[i * 3 + 1]);
    EXPECT_EQ(c->rgba[i * 4 + 3], 255);
  }
}

TEST(ImageDecode, JpegDecodesWithinTheLossOfQuality95) {
  const int w = 48, h = 32;
  const std::vector<uint8_t> card = opaque(test_card(w, h));
  std::vector<uint8_t> jpeg;
  ASSERT_NE(stbi_write_jpg_to_func(append_bytes, &jpeg, w, h, 4, card.data(), 95), 0);
  auto image = decode_image(jpeg, "card.jpg", 1024);
  ASSERT_TRUE(image.ok()) << image.error().message;
  ASSERT_EQ(image->width, uint32_t(w));
  const auto [largest, mean] = difference(image->rgba, card);
  // A smooth card at quality 95 is within a few levels; a swapped channel or a shifted row is off by tens.
  EXPECT_LE(largest, 12);
  EXPECT_LT(mean, 2.0);
  for (size_t i = 3; i < image->rgba.size(); i += 4) ASSERT_EQ(image->rgba[i], 255);
}

TEST(ImageDecode, LosslessWebpRoundTripsExactlyAndLossyIsClose) {
  const int w = 40, h = 24;
  const std::vector<uint8_t> card = test_card(w, h);
  uint8_t* encoded = nullptr;
  size_t size = WebPEncodeLosslessRGBA(card.data(), w, h, w * 4, &encoded);
  ASSERT_GT(size, 0u);
  const std::vector<uint8_t> lossless(encoded, encoded + size);
  WebPFree(encoded);
  auto exact = decode_image(lossless, "card.webp", 1024);
  ASSERT_TRUE(exact.ok()) << exact.error().message;
  EXPECT_EQ(exact->width, uint32_t(w));
  EXPECT_EQ(exact->rgba, card);

  const std::vector<uint8_t> solid = opaque(card);
  size = WebPEncodeRGBA(solid.data(), w, h, w * 4, 95.0f, &encoded);
  ASSERT_GT(size, 0u);
  const std::vector<uint8_t> lossy(encoded, encoded + size);
  WebPFree(encoded);
  auto close = decode_image(lossy, "card-lossy.webp", 1024);
  ASSERT_TRUE(close.ok()) << close.error().message;
  const auto [largest, mean] = difference(close->rgba, solid);
  EXPECT_LE(largest, 24);
  EXPECT_LT(mean, 3.0);
}

TEST(ImageDecode, EachFormatRefusesASizeOverTheLimitFromItsHeader) {
  for (const std::vector<uint8_t>& bytes : in_every_format(40, 2)) {
    ASSERT_GT(bytes.size(), 12u);
    auto r = decode_image(bytes, "wide", 32);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().message,
              "wide: 40x2 pixels is larger than the limit of 32 per side (scale the image down)");
  }
}

TEST(ImageDecode, AJpegClaiming65000SquarePixelsIsRefusedBeforeAnyPixelMemory) {
  std::vector<uint8_t> card = opaque(test_card(8, 8)), jpeg;
  ASSERT_NE(stbi_write_jpg_to_func(append_bytes, &jpeg, 8, 8, 4, card.data(), 90), 0);
  // The baseline frame header (FF C0): length, precision, then height and width, 16 bits each.
  size_t sof = 0;
  for (size_t i = 2; i + 9 < jpeg.size() && !sof; ++i)
    if (jpeg[i] == 0xFF && jpeg[i + 1] == 0xC0) sof = i;
  ASSERT_NE(sof, 0u);
  for (size_t k : {5, 7}) jpeg[sof + k] = 0xFD, jpeg[sof + k + 1] = 0xE8;  // 65000 (libjpeg's own cap: 65500)
  auto r = decode_image(jpeg, "huge.jpg", kMaxPngSide);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("65000x65000 pixels is larger than the limit of 16384"), std::string::npos)
      << r.error().message;
}

TEST(ImageDecode, TheInputsThatBrokeStbImageAreRefusedWithTheLibrarysReason) {
  const std::filesystem::path dir = std::filesystem::path(LAGOON_SOURCE_DIR) / "tests/fuzz/regressions/image";
  struct Case {
    const char* file;
    const char* reason;  // part of the library's message
  };
  for (const Case& c : {Case{"jpeg-huffman-counts-over-256.jpg", "Bogus Huffman table definition"},
                        Case{"jpeg-scan-uses-undefined-huffman-table.jpg", "was not defined"},
                        Case{"png-idat-length-past-the-end.png", "libpng"}}) {
    const std::vector<uint8_t> bytes = file_bytes(dir / c.file);
    ASSERT_FALSE(bytes.empty()) << c.file;
    auto r = decode_image(bytes, c.file, 1024);
    ASSERT_FALSE(r.ok()) << c.file << " decoded";
    EXPECT_EQ(r.error().message.rfind(c.file, 0), 0u) << r.error().message;
    EXPECT_NE(r.error().message.find(c.reason), std::string::npos) << r.error().message;
  }
  // The other two finds were undefined arithmetic inside stb on corrupt data: each decodes to something or
  // is refused, never more.
  for (const char* file : {"jpeg-bit-reader-shift-past-32.jpg", "png-empty-idat-memcpy-null.png"}) {
    auto r = decode_image(file_bytes(dir / file), file, 1024);
    if (!r.ok()) {
      EXPECT_EQ(r.error().message.rfind(file, 0), 0u) << r.error().message;
    }
  }
}

TEST(ImageDecode, TruncatedFilesOfEveryFormatAreRefusedOrDecodeAndNeverCrash) {
  const int w = 16, h = 16;
  for (const std::vector<uint8_t>& bytes : in_every_format(w, h))
    for (size_t cut = 0; cut < bytes.size(); cut += 7) {
      const std::vector<uint8_t> part(bytes.begin(), bytes.begin() + cut);
      auto r = decode_image(part, "cut", 1024);
      if (!r.ok()) {
        EXPECT_EQ(r.error().message.rfind("cut: ", 0), 0u) << r.error().message;
      } else {
        EXPECT_EQ(r->rgba.size(), size_t(w) * h * 4);  // a JPEG's missing tail decodes grey, as in viewers
      }
    }
}

TEST(ImageDecode, AnUnknownSignatureIsNamed) {
  const std::string gif = "GIF89a\x01\x00\x01\x00";
  auto r = decode_image(std::span(reinterpret_cast<const uint8_t*>(gif.data()), gif.size()), "a.gif", 64);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message,
            "a.gif: not a PNG, JPEG or WebP image (its first bytes are no known signature)");
}

TEST(ImageDecode, ReadPngRefusesAJpegUnderAPngName) {
  test::TempDir dir;
  std::vector<uint8_t> card = opaque(test_card(8, 8)), jpeg;
  ASSERT_NE(stbi_write_jpg_to_func(append_bytes, &jpeg, 8, 8, 4, card.data(), 90), 0);
  const auto path = dir.path() / "photo.png";
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(jpeg.data()), std::streamsize(jpeg.size()));
  auto r = read_png(path);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("not a PNG file"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace lagoon::io
