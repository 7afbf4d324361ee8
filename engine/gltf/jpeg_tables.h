// A check of a JPEG's Huffman tables, made before stb_image decodes it. Debian 12's stb_image (git
// 2022-09-08) trusts the 16 code counts of a DHT segment: counts summing to more than 256 make it write past
// its 256- and 257-entry table arrays, on the heap (found by fuzz_image; upstream stb_image 2.28 added the
// same check).
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "core/result.h"

namespace lagoon::gltf::detail {

// `bytes` starts with a JPEG signature. The markers are walked as stb walks them up to the first scan, and
// every 0xFF 0xC4 after it is checked, since stb's position inside scan data cannot be known without decoding
// it. Refuses, naming `where` and the byte offset, any Huffman table that declares more than 256 codes.
Result<void> check_jpeg_huffman_tables(std::span<const uint8_t> bytes, const std::string& where);

}  // namespace lagoon::gltf::detail
