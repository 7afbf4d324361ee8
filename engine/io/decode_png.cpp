// PNG through libpng's simplified API: it converts every PNG kind (grey, palette, 16-bit, tRNS) to RGBA8 and
// checks each chunk's length and CRC as it reads, so nothing is allocated from a length the file only
// claims (ancillary chunks are capped by libpng's own 8 MB chunk limit).
#include <png.h>

#include <memory>

#include "io/image_decode.h"

namespace lagoon::io {

Result<Image8> decode_png(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side) {
  if (sniff_image_format(bytes) != ImageFormat::kPng)
    return make_error(where + ": not a PNG file (wrong signature)");
  const std::string cannot = where + ": cannot decode the PNG (libpng: ";
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    return make_error(cannot + image.message + ")");
  // From here until finish_read, `image` holds libpng's state: freed on every early return.
  std::unique_ptr<png_image, void (*)(png_imagep)> owner(&image, png_image_free);
  if (image.width == 0 || image.height == 0 || image.width > max_side || image.height > max_side)
    return make_error(image_too_large(where, image.width, image.height, max_side));
  image.format = PNG_FORMAT_RGBA;
  Image8 out;
  out.width = image.width;
  out.height = image.height;
  out.rgba.resize(PNG_IMAGE_SIZE(image));
  const bool ok = png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr);
  if (!ok) return make_error(cannot + image.message + ")");
  return out;
}

}  // namespace lagoon::io
