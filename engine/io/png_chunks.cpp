#include "io/png_chunks.h"

namespace lagoon::io {

Result<void> check_png_chunk_lengths(std::span<const uint8_t> b, const std::string& where) {
  constexpr size_t kSignature = 8, kHeader = 8, kCrc = 4;
  for (size_t pos = kSignature; pos + kHeader <= b.size();) {
    const uint64_t length = uint64_t(b[pos]) << 24 | uint64_t(b[pos + 1]) << 16 | uint64_t(b[pos + 2]) << 8 |
                            uint64_t(b[pos + 3]);
    const std::string type(reinterpret_cast<const char*>(&b[pos + 4]), 4);
    const uint64_t available = b.size() - (pos + kHeader);
    if (length > available)
      return make_error(where + ": the PNG's chunk at byte " + std::to_string(pos) + " declares " +
                        std::to_string(length) + " bytes, but only " + std::to_string(available) +
                        " follow (a truncated or hostile file)");
    if (type == "IEND") break;
    pos += kHeader + size_t(length) + kCrc;
  }
  return {};
}

}  // namespace lagoon::io
