#include "gltf/jpeg_tables.h"

#include <algorithm>

namespace lagoon::gltf::detail {
namespace {

constexpr uint8_t kDht = 0xC4, kSos = 0xDA, kEoi = 0xD9;

// Reads as stb_image's memory reader does: past the end every byte is 0.
uint8_t byte_at(std::span<const uint8_t> b, size_t i) {
  return i < b.size() ? b[i] : 0;
}

size_t be16_at(std::span<const uint8_t> b, size_t i) {
  return size_t{byte_at(b, i)} << 8 | byte_at(b, i + 1);
}

// The DHT segment whose length field is at `pos`, read table by table exactly as stb_image's
// stbi__process_marker reads it.
Result<void> check_dht(std::span<const uint8_t> b, size_t pos, const std::string& where) {
  long remaining = long(be16_at(b, pos)) - 2;
  size_t at = pos + 2;
  while (remaining > 0 && at < b.size()) {
    const uint8_t q = byte_at(b, at++);
    if ((q >> 4) > 1 || (q & 15) > 3) return {};  // stb refuses this table itself
    size_t codes = 0;
    for (int i = 0; i < 16; ++i) codes += byte_at(b, at++);
    if (codes > 256)
      return make_error(
          where + ": the JPEG's Huffman table at byte " + std::to_string(pos - 2) + " declares " +
          std::to_string(codes) +
          " codes, more than the 256 a table holds (a corrupt or hostile file; export the image "
          "again)");
    at += codes;
    remaining -= long(17 + codes);
  }
  return {};
}

}  // namespace

Result<void> check_jpeg_huffman_tables(std::span<const uint8_t> b, const std::string& where) {
  // Up to the first start of scan, segment by segment like stb_image: its header loop skips bytes until 0xFF,
  // repeated 0xFF are fill, and every segment it accepts ends where its length says.
  size_t pos = 2;
  for (;;) {
    while (pos < b.size() && b[pos] != 0xFF) ++pos;
    while (pos < b.size() && b[pos] == 0xFF) ++pos;
    if (pos + 2 >= b.size()) return {};
    const uint8_t marker = b[pos++];
    if (marker == kEoi) return {};
    if (marker == kSos) break;
    if (marker == kDht)
      if (auto ok = check_dht(b, pos, where); !ok) return ok;
    const size_t length = be16_at(b, pos);
    if (length < 2) return {};  // stb refuses the file here
    pos += length;
  }
  // Inside scans, decoding decides where stb looks for the next marker, so every 0xFF 0xC4 is checked.
  for (size_t i = pos; i + 1 < b.size(); ++i)
    if (b[i] == 0xFF && b[i + 1] == kDht)
      if (auto ok = check_dht(b, i + 2, where); !ok) return ok;
  return {};
}

}  // namespace lagoon::gltf::detail
