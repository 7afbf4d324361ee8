// Minimal SPIR-V reflection: descriptor bindings, push-constant size, stage and compute workgroup size of a
// single-entry-point module, read straight from the instruction stream (no third-party reflection library).
// Enough to build descriptor set layouts and pipeline layouts from the shaders themselves.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/result.h"

namespace lagoon::vk {

struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t count = 1;  // array size (1 for non-arrays)
  std::string name;    // variable or block name if OpName present, else ""
};

struct ShaderReflection {
  VkShaderStageFlagBits stage = VK_SHADER_STAGE_ALL;  // from the single OpEntryPoint
  std::string entry_point;                            // usually "main"
  // Compute: workgroup size (default values of spec constants if used).
  std::array<uint32_t, 3> local_size{1, 1, 1};
  // SpecId per axis when local_size_{x,y,z}_id is used, else -1.
  std::array<int32_t, 3> local_size_spec_ids{-1, -1, -1};
  std::vector<ReflectedBinding> bindings;  // sorted by (set, binding)
  // Bytes covered by the push-constant block (max member offset + member size), 0 if none.
  uint32_t push_constant_size = 0;
};

// words: a whole SPIR-V module. Errors (bad magic, truncated instruction, more than one entry point,
// unsupported type in a descriptor) return an Error whose message says what is wrong.
Result<ShaderReflection> reflect_spirv(std::span<const uint32_t> words);

}  // namespace lagoon::vk
