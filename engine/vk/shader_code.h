// A SPIR-V module embedded in the binary at build time (see cmake/LagoonShaders.cmake).
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

namespace lagoon::vk {

struct ShaderCode {
  std::string_view name;            // path under shaders/, e.g. "render/sky.frag"; used in error messages
  std::span<const uint32_t> spirv;  // whole module, host byte order
};

}  // namespace lagoon::vk
