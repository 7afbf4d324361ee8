// WebP (lossy, lossless, with alpha) through libwebp, for glTF's EXT_texture_webp. Animated WebP has no
// meaning as a texture and is refused.
#include <webp/decode.h>

#include "io/image_decode.h"

namespace lagoon::io {
namespace {

const char* vp8_reason(VP8StatusCode status) {
  switch (status) {
    case VP8_STATUS_OUT_OF_MEMORY:
      return "out of memory";
    case VP8_STATUS_INVALID_PARAM:
      return "invalid parameter";
    case VP8_STATUS_BITSTREAM_ERROR:
      return "corrupt bitstream";
    case VP8_STATUS_UNSUPPORTED_FEATURE:
      return "unsupported feature";
    case VP8_STATUS_SUSPENDED:
      return "suspended";
    case VP8_STATUS_USER_ABORT:
      return "aborted";
    case VP8_STATUS_NOT_ENOUGH_DATA:
      return "the file ends early";
    case VP8_STATUS_OK:
      break;
  }
  return "unknown error";
}

}  // namespace

Result<Image8> decode_webp(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_side) {
  if (sniff_image_format(bytes) != ImageFormat::kWebp)
    return make_error(where + ": not a WebP file (wrong signature)");
  const std::string cannot = where + ": cannot decode the WebP (libwebp: ";
  WebPBitstreamFeatures features;
  if (const VP8StatusCode s = WebPGetFeatures(bytes.data(), bytes.size(), &features); s != VP8_STATUS_OK)
    return make_error(cannot + vp8_reason(s) + ")");
  if (features.has_animation)
    return make_error(where + ": an animated WebP cannot be a texture (save one frame as a still WebP)");
  if (features.width <= 0 || features.height <= 0 || uint32_t(features.width) > max_side ||
      uint32_t(features.height) > max_side)
    return make_error(image_too_large(where, uint64_t(std::max(features.width, 0)),
                                      uint64_t(std::max(features.height, 0)), max_side));
  Image8 out;
  out.width = uint32_t(features.width);
  out.height = uint32_t(features.height);
  out.rgba.resize(size_t{out.width} * out.height * 4);
  if (!WebPDecodeRGBAInto(bytes.data(), bytes.size(), out.rgba.data(), out.rgba.size(), int(out.width * 4)))
    return make_error(cannot + "corrupt image data)");
  return out;
}

}  // namespace lagoon::io
