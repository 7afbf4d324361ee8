#include "io/png.h"

// Declarations only: the stb implementation is compiled into libstb.
#include <stb_image.h>
#include <stb_image_write.h>

#include <climits>
#include <cstring>
#include <memory>
#include <string>

#include "io/atomic_file.h"
#include "io/png_chunks.h"

namespace lagoon::io {
namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

void append_to_vector(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::byte>*>(context);
  const auto* bytes = static_cast<const std::byte*>(data);
  out->insert(out->end(), bytes, bytes + size);
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
  const int w = static_cast<int>(image.width), h = static_cast<int>(image.height);
  // Rendered frames are opaque: written as RGB they encode ~30 % faster (stb tries five row filters on
  // every byte) and come out smaller; readers get alpha 255 back either way.
  std::vector<uint8_t> rgb;
  bool opaque = true;
  for (size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
  if (opaque) {
    rgb.resize(size_t{image.width} * image.height * 3);
    for (size_t i = 0, n = rgb.size() / 3; i < n; ++i) std::memcpy(&rgb[i * 3], &image.rgba[i * 4], 3);
  }
  const int channels = opaque ? 3 : 4;
  const void* pixels = opaque ? static_cast<const void*>(rgb.data()) : image.rgba.data();
  if (stbi_write_png_to_func(append_to_vector, &encoded, w, h, channels, pixels, w * channels) == 0) {
    return make_error(where + "PNG encoding failed");
  }
  return write_file_atomic(path, encoded);
}

Result<Image8> read_png(const std::filesystem::path& path) {
  Result<std::vector<std::byte>> file = read_file_bytes(path);
  if (!file) return file.error();
  const std::vector<std::byte>& bytes = *file;
  // Checked here because stb would also accept JPEG, BMP, ... and the caller asked for a PNG.
  if (bytes.size() < sizeof kPngSignature || std::memcmp(bytes.data(), kPngSignature, sizeof kPngSignature)) {
    return make_error("cannot read PNG " + path.string() + ": not a PNG file (wrong signature)");
  }
  if (bytes.size() > INT_MAX) return make_error("cannot read PNG " + path.string() + ": file is too large");

  if (auto chunks =
          check_png_chunk_lengths(std::span(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()),
                                  "cannot read PNG " + path.string());
      !chunks)
    return chunks.error();
  int w = 0, h = 0, channels_in_file = 0;
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                            &w, &h, &channels_in_file) &&
      (uint32_t(w) > kMaxPngSide || uint32_t(h) > kMaxPngSide)) {
    return make_error("cannot read PNG " + path.string() + ": " + std::to_string(w) + "x" +
                      std::to_string(h) + " pixels is larger than the limit of " +
                      std::to_string(kMaxPngSide) + " per side (scale the image down)");
  }
  std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()),
                            &w, &h, &channels_in_file, 4),
      &stbi_image_free);
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    return make_error("cannot decode PNG " + path.string() + ": " + (reason ? reason : "unknown error"));
  }
  Image8 image;
  image.width = static_cast<uint32_t>(w);
  image.height = static_cast<uint32_t>(h);
  image.rgba.assign(pixels.get(), pixels.get() + size_t{image.width} * image.height * 4);
  return image;
}

}  // namespace lagoon::io
