// A check of a PNG's chunk lengths, made before stb_image decodes it. stb grows its buffer to an IDAT chunk's
// declared length before it reads the data, so an 800-byte file declaring a 1 GiB chunk makes it allocate 2
// GiB (found by fuzz_image). Every declared length must fit in the bytes that are really there.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "core/result.h"

namespace lagoon::io {

// `bytes` starts with the PNG signature. Walks the chunks as stb does (length, type, data, CRC) up to IEND
// and refuses, naming `where`, the chunk and its byte offset, one whose length runs past the end of `bytes`.
Result<void> check_png_chunk_lengths(std::span<const uint8_t> bytes, const std::string& where);

}  // namespace lagoon::io
