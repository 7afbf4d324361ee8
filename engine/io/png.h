// PNG files for screenshots, golden images and textures (8-bit RGBA only: what the renderer reads back).
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/result.h"

namespace lagoon::io {

struct Image8 {  // 8-bit RGBA, row-major, top row first
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width*height*4

  uint8_t* pixel(uint32_t x, uint32_t y) { return rgba.data() + offset(x, y); }
  const uint8_t* pixel(uint32_t x, uint32_t y) const { return rgba.data() + offset(x, y); }

 private:
  size_t offset(uint32_t x, uint32_t y) const { return (size_t{y} * width + x) * 4; }
};

// Atomic (see AtomicFile); creates missing parent folders. Fails on an empty image or when rgba.size() is
// not width*height*4. Errors name the path and the OS reason.
Result<void> write_png(const std::filesystem::path& path, const Image8& image);

// Largest width or height read_png accepts: 16384² RGBA is 1 GiB, and a small compressed file could otherwise
// claim up to stb's own limit and make it allocate 2 GiB.
inline constexpr uint32_t kMaxPngSide = 16384;

// Any PNG stb can decode (grey, RGB, palette, 16-bit...) comes back as 8-bit RGBA. Errors name the path:
// missing, unreadable, not a PNG, corrupt, larger than kMaxPngSide (checked from the header, before
// decoding).
Result<Image8> read_png(const std::filesystem::path& path);

}  // namespace lagoon::io
