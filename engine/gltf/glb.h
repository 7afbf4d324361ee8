// The binary glTF container (.glb): a 12-byte header, a JSON chunk, an optional BIN chunk.
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

#include "core/result.h"

namespace lagoon::gltf::detail {

// True when the bytes start with the GLB magic "glTF" (whatever the file's extension says).
bool is_glb(std::span<const uint8_t> file);

// The JSON chunk, after checking every length in the container against the file size. tinygltf 2.7 checks
// the BIN chunk's length against the header without its 8-byte chunk header and would read past the end.
Result<std::string_view> glb_json_chunk(std::span<const uint8_t> file);

}  // namespace lagoon::gltf::detail
