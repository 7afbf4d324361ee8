// PNG and JPEG (the two image formats glTF 2.0 allows) decoded to RGBA8 through stb_image.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "core/result.h"
#include "gltf/model.h"

namespace lagoon::gltf::detail {

// `where` names the image in messages ("images[2] 'bark'"). Anything but PNG or JPEG is refused by its
// signature before stb sees it, and the size is read from the header and checked against `max_size`
// before any pixel memory is allocated.
Result<Texture> decode_image(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_size);

}  // namespace lagoon::gltf::detail
