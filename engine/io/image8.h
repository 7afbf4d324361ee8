// An 8-bit RGBA image in memory: what the decoders produce and the PNG writer takes.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lagoon::io {

struct Image8 {  // 8-bit RGBA, row-major, top row first
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width*height*4

  uint8_t* pixel(uint32_t x, uint32_t y) { return rgba.data() + offset(x, y); }
  const uint8_t* pixel(uint32_t x, uint32_t y) const { return rgba.data() + offset(x, y); }

 private:
  size_t offset(uint32_t x, uint32_t y) const { return (size_t{y} * width + x) * 4; }
};

}  // namespace lagoon::io
