#include "gltf/image_decode.h"

#include "io/image_decode.h"

namespace lagoon::gltf::detail {

Result<Texture> decode_image(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_size) {
  Result<io::Image8> image = io::decode_image(bytes, where, max_size);
  if (!image) return image.error();
  Texture texture;
  texture.width = image->width;
  texture.height = image->height;
  texture.rgba = std::move(image->rgba);
  return texture;
}

}  // namespace lagoon::gltf::detail
