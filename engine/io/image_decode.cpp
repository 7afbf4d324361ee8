#include "io/image_decode.h"

#include <cstring>

namespace lagoon::io {

ImageFormat sniff_image_format(std::span<const uint8_t> b) {
  static constexpr uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (b.size() >= 8 && std::memcmp(b.data(), kPng, 8) == 0) return ImageFormat::kPng;
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return ImageFormat::kJpeg;
  if (b.size() >= 12 && std::memcmp(b.data(), "RIFF", 4) == 0 && std::memcmp(b.data() + 8, "WEBP", 4) == 0)
    return ImageFormat::kWebp;
  return ImageFormat::kUnknown;
}

const char* image_format_name(ImageFormat format) {
  switch (format) {
    case ImageFormat::kPng:
      return "PNG";
    case ImageFormat::kJpeg:
      return "JPEG";
    case ImageFormat::kWebp:
      return "WebP";
    case ImageFormat::kUnknown:
      break;
  }
  return "unknown";
}

std::string image_too_large(const std::string& where, uint64_t width, uint64_t height, uint32_t max_side) {
  return where + ": " + std::to_string(width) + "x" + std::to_string(height) +
         " pixels is larger than the limit of " + std::to_string(max_side) +
         " per side (scale the image down)";
}

Result<Image8> decode_image(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side) {
  switch (sniff_image_format(bytes)) {
    case ImageFormat::kPng:
      return decode_png(bytes, where, max_side);
    case ImageFormat::kJpeg:
      return decode_jpeg(bytes, where, max_side);
    case ImageFormat::kWebp:
      return decode_webp(bytes, where, max_side);
    case ImageFormat::kUnknown:
      break;
  }
  return make_error(where + ": not a PNG, JPEG or WebP image (its first bytes are no known signature)");
}

}  // namespace lagoon::io
