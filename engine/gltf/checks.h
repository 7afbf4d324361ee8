// Small shared helpers of the glTF loader: object names for messages, index and overflow checks, warnings.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lagoon::gltf::detail {

// "accessors[3]": how the glTF spec (and every validator) names an object, so users can find it.
inline std::string at(std::string_view array, int64_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

// glTF indices come from the file as ints: negative and too-large values are both possible.
inline bool valid_index(int64_t index, size_t count) {
  return index >= 0 && static_cast<uint64_t>(index) < count;
}

// a * b + c, false when it does not fit: sizes from the file may be chosen to wrap around.
inline bool mul_add(size_t a, size_t b, size_t c, size_t* out) {
  size_t product = 0;
  return !__builtin_mul_overflow(a, b, &product) && !__builtin_add_overflow(product, c, out);
}

// Warnings are per feature kind: one line per kind, however often the file uses it.
inline void warn_once(std::vector<std::string>& warnings, std::string message) {
  for (const std::string& w : warnings) {
    if (w == message) return;
  }
  warnings.push_back(std::move(message));
}

// The extensions the loader reads (issue 17); every other one is skipped with one warning, and a file that
// requires another one is refused.
inline bool supported_extension(std::string_view name) {
  return name == "KHR_lights_punctual" || name == "KHR_texture_transform" ||
         name == "KHR_materials_emissive_strength" || name == "KHR_mesh_quantization" ||
         name == "EXT_texture_webp";
}

}  // namespace lagoon::gltf::detail
