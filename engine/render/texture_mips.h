// A texture's mip chain made on the CPU, uploaded with plain copies. lavapipe implements a filtering blit
// (what vk/mipmaps.h records) as a draw through its blitter, whose shaders it compiles at the first blit of
// every process: 125-170 ms of the default scene's 1.2 s warm render went to the 256² floor texture's mips
// (docs/building.md). The filter is the blit's: each level from the one above, sampled bilinearly at the
// level's texel centres with the edges clamped (a 2 x 2 mean where the size halves), in linear light for
// sRGB textures, rounded to the nearest 8-bit value. The same chain on every device.
#pragma once
#include <cstdint>
#include <vector>

#include "io/image8.h"

namespace lagoon::render {

// Levels down to 1 x 1, as vk::ImageDesc's mip_levels = 0 makes them: bit_width(max(width, height)).
uint32_t mip_count(uint32_t width, uint32_t height);

// Every level of `image` (RGBA8, `srgb` colour or linear data), level 0 first, each tightly packed.
std::vector<uint8_t> rgba8_mip_chain(const io::Image8& image, bool srgb);

}  // namespace lagoon::render
