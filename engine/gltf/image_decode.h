// A glTF image (PNG or JPEG, as glTF 2.0 allows, or WebP with EXT_texture_webp) decoded to RGBA8 by
// io::decode_image (libpng, libjpeg-turbo, libwebp).
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "core/result.h"
#include "gltf/model.h"

namespace lagoon::gltf::detail {

// `where` names the image in messages ("images[2] 'bark'"). Any other format is refused by its signature,
// and the size is read from the header and checked against `max_size` before any pixel memory is
// allocated.
Result<Texture> decode_image(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_size);

}  // namespace lagoon::gltf::detail
