#include "gltf/image_decode.h"

#include "gltf/jpeg_tables.h"
#include "io/png_chunks.h"

// Declarations only: the stb implementation is compiled into libstb.
#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

namespace lagoon::gltf::detail {
namespace {

bool is_png(std::span<const uint8_t> b) {
  static constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return b.size() >= 8 && std::memcmp(b.data(), kSignature, 8) == 0;
}

bool is_jpeg(std::span<const uint8_t> b) {
  return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF;
}

}  // namespace

Result<Texture> decode_image(std::span<const uint8_t> bytes, const std::string& where, uint32_t max_size) {
  if (!is_png(bytes) && !is_jpeg(bytes)) {
    return make_error(where + ": not a PNG or JPEG image (the only formats glTF 2.0 allows)");
  }
  if (bytes.size() > INT_MAX) return make_error(where + ": the image data is larger than 2 GiB");
  if (is_jpeg(bytes))
    if (auto tables = check_jpeg_huffman_tables(bytes, where); !tables) return tables.error();
  if (is_png(bytes))
    if (auto chunks = io::check_png_chunk_lengths(bytes, where); !chunks) return chunks.error();
  const int size = static_cast<int>(bytes.size());
  const std::string cannot =
      where + ": cannot decode the " + (is_png(bytes) ? "PNG" : "JPEG") + " (stb_image: ";
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(bytes.data(), size, &w, &h, &channels)) {
    return make_error(cannot + stbi_failure_reason() + ")");
  }
  if (w <= 0 || h <= 0 || static_cast<uint32_t>(w) > max_size || static_cast<uint32_t>(h) > max_size) {
    return make_error(where + ": " + std::to_string(w) + "x" + std::to_string(h) +
                      " pixels is larger than the texture size limit of " + std::to_string(max_size));
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(bytes.data(), size, &w, &h, &channels, 4), stbi_image_free);
  if (!pixels) return make_error(cannot + stbi_failure_reason() + ")");
  // The header said one size; a broken file may decode to another. Trust only what was decoded.
  if (w <= 0 || h <= 0 || static_cast<uint32_t>(w) > max_size || static_cast<uint32_t>(h) > max_size) {
    return make_error(where + ": decoded to " + std::to_string(w) + "x" + std::to_string(h) + " pixels");
  }
  Texture texture;
  texture.width = static_cast<uint32_t>(w);
  texture.height = static_cast<uint32_t>(h);
  texture.rgba.assign(pixels.get(), pixels.get() + size_t{texture.width} * texture.height * 4);
  return texture;
}

}  // namespace lagoon::gltf::detail
