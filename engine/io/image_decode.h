// PNG, JPEG and WebP decoded to 8-bit RGBA by Debian's maintained libraries: libpng, libjpeg-turbo and
// libwebp (issue 36: they replaced stb_image and the guards Lagoon kept in front of it). Every decoder reads
// the size from the header and refuses it against `max_side` before any pixel memory is allocated, and never
// prints: each failure comes back as a message naming `where`, the format and the library's reason.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "core/result.h"
#include "io/image8.h"

namespace lagoon::io {

enum class ImageFormat { kUnknown, kPng, kJpeg, kWebp };

// From the signature: PNG's 8 bytes, JPEG's FF D8 FF, WebP's "RIFF....WEBP".
ImageFormat sniff_image_format(std::span<const uint8_t> bytes);
const char* image_format_name(ImageFormat format);  // "PNG", "JPEG", "WebP", "unknown"

// Decodes whichever of the three `bytes` holds (as its signature says). `where` starts every message
// ("images[2] 'bark'", "floor.png"). Larger than `max_side` pixels on a side is refused from the header.
Result<Image8> decode_image(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side);

// One format each; the signature must match (decode_image dispatches to them).
Result<Image8> decode_png(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side);
Result<Image8> decode_jpeg(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side);
Result<Image8> decode_webp(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side);

// The message for a size over `max_side`, shared by the three decoders.
std::string image_too_large(const std::string& where, uint64_t width, uint64_t height, uint32_t max_side);

}  // namespace lagoon::io
