#include "gltf/jpeg_tables.h"

#include <algorithm>
#include <tuple>

namespace lagoon::gltf::detail {
namespace {

constexpr uint8_t kDht = 0xC4, kSos = 0xDA, kEoi = 0xD9, kSofProgressive = 0xC2;

// Which Huffman tables have been defined so far: [class: 0 DC, 1 AC][id 0..3]. stb_image does not clear its
// tables, so a scan that uses one never defined decodes with uninitialised memory and indexes past its arrays
// (found by fuzz_image; upstream stb_image 2.28 added a bounds check for it).
struct Tables {
  bool defined[2][4] = {};
  bool progressive = false;
};

// Reads as stb_image's memory reader does: past the end every byte is 0.
uint8_t byte_at(std::span<const uint8_t> b, size_t i) {
  return i < b.size() ? b[i] : 0;
}

size_t be16_at(std::span<const uint8_t> b, size_t i) {
  return size_t{byte_at(b, i)} << 8 | byte_at(b, i + 1);
}

// The DHT segment whose length field is at `pos`, read table by table exactly as stb_image's
// stbi__process_marker reads it.
Result<void> check_dht(std::span<const uint8_t> b, size_t pos, Tables& tables, const std::string& where) {
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
    tables.defined[q >> 4][q & 15] = true;
    at += codes;
    remaining -= long(17 + codes);
  }
  return {};
}

// The scan header whose length field is at `pos`: every table its components use, as stb decodes the scan
// (baseline: DC and AC; progressive: DC for a first DC scan, AC for an AC scan), must be defined before it.
Result<void> check_sos(std::span<const uint8_t> b, size_t pos, const Tables& tables,
                       const std::string& where) {
  const size_t components = byte_at(b, pos + 2);
  const uint8_t spectral_start = byte_at(b, pos + 3 + 2 * components);
  const uint8_t successive_high = byte_at(b, pos + 5 + 2 * components) >> 4;
  const bool uses_dc = !tables.progressive || (spectral_start == 0 && successive_high == 0);
  const bool uses_ac = !tables.progressive || spectral_start > 0;
  for (size_t k = 0; k < components && k < 4; ++k) {
    const uint8_t ids = byte_at(b, pos + 4 + 2 * k);
    for (auto [used, cls, id] : {std::tuple{uses_dc, 0, ids >> 4}, std::tuple{uses_ac, 1, ids & 15}})
      if (used && id < 4 && !tables.defined[cls][id])
        return make_error(where + ": the JPEG's scan at byte " + std::to_string(pos - 2) +
                          " uses Huffman table " + (cls == 0 ? "DC " : "AC ") + std::to_string(id) +
                          ", which the file does not define before it (a corrupt or hostile file)");
  }
  return {};
}

}  // namespace

Result<void> check_jpeg_huffman_tables(std::span<const uint8_t> b, const std::string& where) {
  // Up to the first start of scan, segment by segment like stb_image: its header loop skips bytes until 0xFF,
  // repeated 0xFF are fill, and every segment it accepts ends where its length says.
  Tables tables;
  size_t pos = 2;
  for (;;) {
    while (pos < b.size() && b[pos] != 0xFF) ++pos;
    while (pos < b.size() && b[pos] == 0xFF) ++pos;
    if (pos + 2 >= b.size()) return {};
    const uint8_t marker = b[pos++];
    if (marker == kEoi) return {};
    if (marker == kSos) {
      if (auto ok = check_sos(b, pos, tables, where); !ok) return ok;
      break;
    }
    if (marker == kSofProgressive) tables.progressive = true;
    if (marker == kDht)
      if (auto ok = check_dht(b, pos, tables, where); !ok) return ok;
    const size_t length = be16_at(b, pos);
    if (length < 2) return {};  // stb refuses the file here
    pos += length;
  }
  // Inside scans, decoding decides where stb looks for the next marker, so every 0xFF 0xC4 and 0xFF 0xDA is
  // checked, in order (scan data holds neither: a 0xFF there is followed by 0x00 or a restart marker).
  for (size_t i = pos; i + 1 < b.size(); ++i) {
    if (b[i] != 0xFF) continue;
    if (b[i + 1] == kDht)
      if (auto ok = check_dht(b, i + 2, tables, where); !ok) return ok;
    if (b[i + 1] == kSos)
      if (auto ok = check_sos(b, i + 2, tables, where); !ok) return ok;
  }
  return {};
}

}  // namespace lagoon::gltf::detail
