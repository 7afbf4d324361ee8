#include "io/png.h"

#include <png.h>

#include <climits>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>

#include "io/atomic_file.h"
#include "io/image_decode.h"

namespace lagoon::io {
namespace {

// libpng's output into memory; running out of it is reported as libpng's error (longjmp), never thrown
// through C.
void append_png_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::byte>*>(png_get_io_ptr(png));
  try {
    out->insert(out->end(), reinterpret_cast<const std::byte*>(data),
                reinterpret_cast<const std::byte*>(data) + size);
  } catch (const std::bad_alloc&) {
    png_error(png, "out of memory");
  }
}

void no_flush(png_structp) {}

// libpng's errors end the encoding with their message kept (the default handler prints it to stderr).
struct PngFailure {
  char message[160] = "";
};
[[noreturn]] void keep_png_error(png_structp png, png_const_charp message) {
  auto* failure = static_cast<PngFailure*>(png_get_error_ptr(png));
  std::snprintf(failure->message, sizeof failure->message, "%s", message);
  png_longjmp(png, 1);
}
void ignore_png_warning(png_structp, png_const_charp) {}

// Encodes 8-bit rows of `channels` (3: RGB, 4: RGBA) into `out`. The Sub filter and zlib level 2: a rendered
// 1280x720 frame in ~35 ms (stb_image_write, trying five filters per row at level 8: ~200 ms), and smaller.
// false with libpng's reason in `failure`. Only plain data lives across setjmp, as libpng requires.
bool encode_png(const uint8_t* pixels, uint32_t width, uint32_t height, int channels,
                std::vector<std::byte>* out, PngFailure* failure) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, failure, keep_png_error, ignore_png_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, out, append_png_bytes, no_flush);
  png_set_compression_level(png, 2);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(png, info, width, height, 8, channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const size_t stride = size_t{width} * size_t(channels);
  for (uint32_t y = 0; y < height; ++y) png_write_row(png, pixels + y * stride);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

Result<void> write_png(const std::filesystem::path& path, const Image8& image) {
  const std::string where = "cannot write PNG " + path.string() + ": ";
  if (image.width == 0 || image.height == 0) return make_error(where + "image is empty");
  // stb takes int sizes and a byte stride; reject what would overflow instead of writing garbage.
  if (image.width > INT_MAX / 4 || image.height > INT_MAX) return make_error(where + "image is too large");
  const size_t expected = size_t{image.width} * image.height * 4;
  if (image.rgba.size() != expected) {
    return make_error(where + "rgba has " + std::to_string(image.rgba.size()) + " bytes, " +
                      std::to_string(image.width) + "x" + std::to_string(image.height) + " RGBA needs " +
                      std::to_string(expected));
  }
  std::vector<std::byte> encoded;
  // Rendered frames are opaque: written as RGB they encode faster and come out smaller; readers get alpha 255
  // back either way.
  std::vector<uint8_t> rgb;
  bool opaque = true;
  for (size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
  if (opaque) {
    rgb.resize(size_t{image.width} * image.height * 3);
    for (size_t i = 0, n = rgb.size() / 3; i < n; ++i) std::memcpy(&rgb[i * 3], &image.rgba[i * 4], 3);
  }
  const int channels = opaque ? 3 : 4;
  const uint8_t* pixels = opaque ? rgb.data() : image.rgba.data();
  PngFailure failure;
  if (!encode_png(pixels, image.width, image.height, channels, &encoded, &failure))
    return make_error(where + "libpng: " + (failure.message[0] ? failure.message : "out of memory"));
  return write_file_atomic(path, encoded);
}

Result<Image8> read_png(const std::filesystem::path& path) {
  Result<std::vector<std::byte>> file = read_file_bytes(path);
  if (!file) return file.error();
  const std::span bytes(reinterpret_cast<const uint8_t*>(file->data()), file->size());
  // The caller asked for a PNG: a JPEG or WebP under a .png name is refused, not decoded.
  if (sniff_image_format(bytes) != ImageFormat::kPng)
    return make_error("cannot read PNG " + path.string() + ": not a PNG file (wrong signature)");
  return decode_png(bytes, "cannot read PNG " + path.string(), kMaxPngSide);
}

}  // namespace lagoon::io
