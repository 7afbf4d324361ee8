#include "gltf/glb.h"

#include <cstring>
#include <string>

namespace lagoon::gltf::detail {
namespace {

constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON", little-endian
constexpr uint32_t kBinChunk = 0x004E4942;   // "BIN\0"

// GLB is little-endian; so is every machine Lagoon runs on.
uint32_t u32_at(std::span<const uint8_t> bytes, size_t offset) {
  uint32_t v = 0;
  std::memcpy(&v, bytes.data() + offset, sizeof v);
  return v;
}

}  // namespace

bool is_glb(std::span<const uint8_t> file) {
  return file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
}

Result<std::string_view> glb_json_chunk(std::span<const uint8_t> file) {
  const std::string what = "not a valid binary glTF (GLB): ";
  if (file.size() < 20) return make_error(what + "the file is shorter than the 20-byte header");
  if (!is_glb(file)) return make_error(what + "the magic is not 'glTF'");
  const uint32_t version = u32_at(file, 4);
  if (version != 2) {
    return make_error(what + "container version " + std::to_string(version) +
                      "; only version 2 is supported");
  }
  // Only `length` bytes belong to the GLB; the rest of the file (if any) is ignored, as the spec asks.
  const uint64_t length = u32_at(file, 8);
  if (length > file.size()) {
    return make_error(what + "the header says " + std::to_string(length) + " bytes but the file has " +
                      std::to_string(file.size()));
  }
  const uint64_t json_length = u32_at(file, 12);
  if (u32_at(file, 16) != kJsonChunk) return make_error(what + "the first chunk is not JSON");
  if (json_length == 0 || 20 + json_length > length) {
    return make_error(what + "the JSON chunk length " + std::to_string(json_length) +
                      " does not fit in the file");
  }
  const uint64_t bin_start = 20 + json_length;
  if (bin_start < length) {
    if (bin_start + 8 > length) return make_error(what + "the second chunk's header is cut off");
    const uint64_t bin_length = u32_at(file, bin_start);
    if (bin_start + 8 + bin_length > length) {
      return make_error(what + "the second chunk (" + std::to_string(bin_length) +
                        " bytes) runs past the end of the file");
    }
    if (u32_at(file, bin_start + 4) != kBinChunk) return make_error(what + "the second chunk is not BIN");
  }
  return std::string_view(reinterpret_cast<const char*>(file.data()) + 20, json_length);
}

}  // namespace lagoon::gltf::detail
