// PNG files for screenshots, golden images and textures (8-bit RGBA only: what the renderer reads back).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/result.h"
#include "io/image8.h"

namespace lagoon::io {

// Atomic (see AtomicFile); creates missing parent folders. Fails on an empty image or when rgba.size() is
// not width*height*4. Errors name the path and the OS reason.
Result<void> write_png(const std::filesystem::path& path, const Image8& image);

// Largest width or height read_png accepts: 16384² RGBA is 1 GiB, and a small compressed file could otherwise
// claim up to libpng's own limit of a million pixels a side.
inline constexpr uint32_t kMaxPngSide = 16384;

// Any PNG libpng decodes (grey, RGB, palette, 16-bit...) comes back as 8-bit RGBA (io/image_decode.h). Errors
// name the path: missing, unreadable, not a PNG, corrupt, larger than kMaxPngSide (checked from the header,
// before decoding).
Result<Image8> read_png(const std::filesystem::path& path);

}  // namespace lagoon::io
