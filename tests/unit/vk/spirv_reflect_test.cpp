// Tests for the SPIR-V reflection module. Most cases reflect GLSL test shaders under tests/shaders/reflect,
// compiled by glslang at build time (target vulkan1.2 -> SPIR-V 1.5, with -g0 so OpName is stripped and
// names are not checked on them); a small hand assembler covers what glslang does not emit at that target
// (LocalSizeId, Uniform + BufferBlock), names, and malformed modules.
#include "vk/spirv_reflect.h"

#include <gtest/gtest.h>

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "lagoon_test_shaders/shaders.h"

namespace lagoon::vk {
namespace {

namespace shaders = ::lagoon::shaders;

using Row = std::tuple<uint32_t, uint32_t, VkDescriptorType, uint32_t>;  // set, binding, type, count

std::vector<Row> rows(const ShaderReflection& r) {
  std::vector<Row> out;
  for (const ReflectedBinding& b : r.bindings) out.emplace_back(b.set, b.binding, b.type, b.count);
  return out;
}

// Message of a reflection that is expected to fail, or a marker that makes the test's expectation fail.
std::string error_of(std::span<const uint32_t> words) {
  auto r = reflect_spirv(words);
  return r.ok() ? "<reflection unexpectedly succeeded>" : r.error().message;
}

constexpr std::array<int32_t, 3> kNoSpecIds{-1, -1, -1};

TEST(SpirvReflect, StorageAndUniformBuffersInTwoSetsSorted) {
  auto r = reflect_spirv(shaders::reflect_buffers_comp.spirv);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->stage, VK_SHADER_STAGE_COMPUTE_BIT);
  EXPECT_EQ(r->entry_point, "main");
  EXPECT_EQ(r->local_size, (std::array<uint32_t, 3>{64, 2, 1}));
  EXPECT_EQ(r->local_size_spec_ids, kNoSpecIds);
  EXPECT_EQ(r->push_constant_size, 0u);
  // The shader declares set 1 first and the set-0 bindings out of order.
  EXPECT_EQ(rows(*r), (std::vector<Row>{
                          {0, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                          {0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1},
                          {0, 2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                          {1, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},  // Counters counters[2]
                      }));
}

TEST(SpirvReflect, ImageSamplerAndTexelBufferDescriptorsInFragmentShader) {
  auto r = reflect_spirv(shaders::reflect_textures_frag.spirv);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->stage, VK_SHADER_STAGE_FRAGMENT_BIT);
  EXPECT_EQ(r->entry_point, "main");
  EXPECT_EQ(r->push_constant_size, 0u);
  EXPECT_EQ(rows(*r), (std::vector<Row>{
                          {0, 0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},  // sampler2D
                          {0, 1, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1},           // texture2D
                          {0, 2, VK_DESCRIPTOR_TYPE_SAMPLER, 1},                 // sampler
                          {0, 3, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1},           // image2D rgba32f
                          {0, 4, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1},    // samplerBuffer
                          {0, 5, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1},    // textureBuffer
                          {0, 6, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, 1},    // imageBuffer
                          {1, 0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3},  // sampler2D layers[3]
                          {2, 1, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 4},           // texture2D cascades[4]
                      }));
}

TEST(SpirvReflect, VertexShaderPushConstantSizeMatchesStd430) {
  auto r = reflect_spirv(shaders::reflect_push_vert.spirv);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->stage, VK_SHADER_STAGE_VERTEX_BIT);
  EXPECT_EQ(r->local_size, (std::array<uint32_t, 3>{1, 1, 1}));
  EXPECT_EQ(rows(*r), (std::vector<Row>{{0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}}));
  // Push-constant blocks use std430:
  //   mat4 model    offset  0, 4 columns * MatrixStride 16 = 64 bytes
  //   vec4 tint     offset 64, 16 bytes
  //   float time    offset 80, 4 bytes                -> 84
  //   vec2 wind[3]  aligned to 8 -> offset 88, ArrayStride 8 * 3 = 24 bytes
  // End of the last member: 88 + 24 = 112.
  EXPECT_EQ(r->push_constant_size, 112u);
}

TEST(SpirvReflect, PushConstantSizeWithNestedStructsAndRowMajorMatrix) {
  auto r = reflect_spirv(shaders::reflect_push_nested_comp.spirv);
  ASSERT_TRUE(r.ok()) << r.error().message;
  // std430: struct Wave { vec2 dir; float amp; } has alignment 8 and ArrayStride 16.
  //   Wave waves[2]               offset  0, 2 * 16 = 32 bytes
  //   Group { uint id; Wave wave; } offset 32; wave at 32 + 8, covering 12 bytes -> ends at 52
  //   row_major mat2x3 m          rows are vec2: alignment 8 -> offset 56, 3 rows * MatrixStride 8 = 24
  // End of the last member: 56 + 24 = 80 (column-major would have been offset 64 + 2 * 16 = 96).
  EXPECT_EQ(r->push_constant_size, 80u);
  EXPECT_EQ(rows(*r), (std::vector<Row>{{0, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}}));
}

TEST(SpirvReflect, WorkgroupSizeFromSpecializationConstants) {
  auto r = reflect_spirv(shaders::reflect_spec_size_comp.spirv);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->stage, VK_SHADER_STAGE_COMPUTE_BIT);
  // local_size_x = 16 with local_size_x_id = 3; y fixed at 4; z defaults to 1 with local_size_z_id = 5.
  EXPECT_EQ(r->local_size, (std::array<uint32_t, 3>{16, 4, 1}));
  EXPECT_EQ(r->local_size_spec_ids, (std::array<int32_t, 3>{3, -1, 5}));
}

TEST(SpirvReflect, UnsizedDescriptorArrayIsAnError) {
  EXPECT_NE(
      error_of(shaders::reflect_unsized_array_frag.spirv).find("unsized descriptor arrays are not supported"),
      std::string::npos);
}

TEST(SpirvReflect, AccelerationStructureIsAnError) {
  EXPECT_NE(error_of(shaders::reflect_ray_query_comp.spirv).find("acceleration structures are not supported"),
            std::string::npos);
}

TEST(SpirvReflect, EmptyModuleIsAnError) {
  EXPECT_NE(error_of({}).find("empty"), std::string::npos);
}

TEST(SpirvReflect, ModuleShorterThanHeaderIsAnError) {
  const std::vector<uint32_t> words{0x07230203, 0x00010500, 0};
  EXPECT_NE(error_of(words).find("too short"), std::string::npos);
}

TEST(SpirvReflect, BadMagicIsAnError) {
  std::vector<uint32_t> words(shaders::reflect_buffers_comp.spirv.begin(),
                              shaders::reflect_buffers_comp.spirv.end());
  words[0] = 0xdeadbeef;
  const std::string message = error_of(words);
  EXPECT_NE(message.find("bad magic"), std::string::npos) << message;
  EXPECT_NE(message.find("0xdeadbeef"), std::string::npos) << message;

  words[0] = 0x03022307;  // byte-swapped magic
  EXPECT_NE(error_of(words).find("byte order"), std::string::npos);
}

TEST(SpirvReflect, TruncatedModuleIsAnError) {
  const std::span<const uint32_t> words = shaders::reflect_textures_frag.spirv;
  // Cut the module inside the first multi-word instruction past its middle.
  size_t pos = 5;
  while (pos < words.size() && (pos < words.size() / 2 || (words[pos] >> 16) < 2)) pos += words[pos] >> 16;
  ASSERT_LT(pos, words.size());
  const std::string message = error_of(words.first(pos + 1));
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(SpirvReflect, ZeroWordCountIsAnError) {
  std::vector<uint32_t> words(shaders::reflect_push_vert.spirv.begin(),
                              shaders::reflect_push_vert.spirv.end());
  words.push_back(0);  // an instruction word claiming 0 words would loop forever if accepted
  EXPECT_NE(error_of(words).find("word count of 0"), std::string::npos);
}

// Hand-assembled modules. Enumerant values from the SPIR-V unified spec.
constexpr uint32_t kOpName = 5, kOpMemoryModel = 14, kOpEntryPoint = 15, kOpCapability = 17, kOpTypeInt = 21,
                   kOpTypeStruct = 30, kOpTypePointer = 32, kOpConstant = 43, kOpSpecConstant = 50,
                   kOpVariable = 59, kOpDecorate = 71, kOpMemberDecorate = 72, kOpExecutionModeId = 331;
constexpr uint32_t kSpecId = 1, kBlock = 2, kBufferBlock = 3, kBinding = 33, kDescriptorSet = 34,
                   kOffset = 35;
constexpr uint32_t kGLCompute = 5, kFragment = 4, kUniform = 2, kLocalSizeId = 38;

class Assembler {
 public:
  Assembler& op(uint32_t opcode, std::vector<uint32_t> operands) {
    words_.push_back(static_cast<uint32_t>(operands.size() + 1) << 16 | opcode);
    words_.insert(words_.end(), operands.begin(), operands.end());
    return *this;
  }
  // Operands followed by a NUL-terminated literal string packed low byte first.
  Assembler& op(uint32_t opcode, std::vector<uint32_t> operands, std::string_view text) {
    for (size_t i = 0; i <= text.size(); i += 4) {
      uint32_t word = 0;
      for (size_t b = 0; b < 4 && i + b < text.size(); ++b) word |= uint32_t{uint8_t(text[i + b])} << (8 * b);
      operands.push_back(word);
    }
    return op(opcode, std::move(operands));
  }
  std::span<const uint32_t> words() const { return words_; }

 private:
  std::vector<uint32_t> words_{0x07230203, 0x00010600, 0, 100, 0};  // SPIR-V 1.6, id bound 100
};

Assembler compute_module() {
  Assembler a;
  a.op(kOpCapability, {1}).op(kOpMemoryModel, {0, 1}).op(kOpEntryPoint, {kGLCompute, 1}, "main");
  return a;
}

// %2 = uint; %struct_id = struct { uint } at offset 0, decorated `block_decoration`;
// %var_id = Uniform variable of it at (set, binding).
void add_uniform_struct(Assembler& a, uint32_t struct_id, uint32_t var_id, uint32_t block_decoration,
                        uint32_t set, uint32_t binding) {
  a.op(kOpDecorate, {struct_id, block_decoration})
      .op(kOpMemberDecorate, {struct_id, 0, kOffset, 0})
      .op(kOpDecorate, {var_id, kDescriptorSet, set})
      .op(kOpDecorate, {var_id, kBinding, binding})
      .op(kOpTypeStruct, {struct_id, 2})
      .op(kOpTypePointer, {struct_id + 50, kUniform, struct_id})
      .op(kOpVariable, {struct_id + 50, var_id, kUniform});
}

TEST(SpirvReflect, HandAssembledLocalSizeIdBufferBlockAndNames) {
  Assembler a = compute_module();
  a.op(kOpExecutionModeId, {1, kLocalSizeId, 20, 21, 22})
      .op(kOpName, {10}, "Legacy")
      .op(kOpName, {11}, "")  // anonymous instance: the block name is reported
      .op(kOpName, {14}, "params")
      .op(kOpDecorate, {20, kSpecId, 7})
      .op(kOpTypeInt, {2, 32, 0});
  add_uniform_struct(a, 10, 11, kBufferBlock, 2, 5);  // pre-SPIR-V 1.3 storage buffer
  add_uniform_struct(a, 13, 14, kBlock, 0, 7);
  a.op(kOpSpecConstant, {2, 20, 8}).op(kOpConstant, {2, 21, 2}).op(kOpConstant, {2, 22, 1});

  auto r = reflect_spirv(a.words());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->stage, VK_SHADER_STAGE_COMPUTE_BIT);
  EXPECT_EQ(r->entry_point, "main");
  EXPECT_EQ(r->local_size, (std::array<uint32_t, 3>{8, 2, 1}));
  EXPECT_EQ(r->local_size_spec_ids, (std::array<int32_t, 3>{7, -1, -1}));
  ASSERT_EQ(r->bindings.size(), 2u);
  EXPECT_EQ(rows(*r), (std::vector<Row>{{0, 7, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                        {2, 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}}));
  EXPECT_EQ(r->bindings[0].name, "params");
  EXPECT_EQ(r->bindings[1].name, "Legacy");
}

TEST(SpirvReflect, MoreThanOneEntryPointIsAnError) {
  Assembler a = compute_module();
  a.op(kOpEntryPoint, {kFragment, 2}, "frag_main");
  const std::string message = error_of(a.words());
  EXPECT_NE(message.find("more than one entry point"), std::string::npos) << message;
  EXPECT_NE(message.find("frag_main"), std::string::npos) << message;
}

TEST(SpirvReflect, MissingEntryPointIsAnError) {
  Assembler a;
  a.op(kOpCapability, {1}).op(kOpMemoryModel, {0, 1});
  EXPECT_NE(error_of(a.words()).find("no OpEntryPoint"), std::string::npos);
}

TEST(SpirvReflect, UniformStructWithoutBlockDecorationIsAnError) {
  Assembler a = compute_module();
  a.op(kOpTypeInt, {2, 32, 0});
  constexpr uint32_t kRelaxedPrecision = 0;  // stands in for the missing Block
  add_uniform_struct(a, 10, 11, kRelaxedPrecision, 0, 0);
  const std::string message = error_of(a.words());
  EXPECT_NE(message.find("neither Block nor BufferBlock"), std::string::npos) << message;
  EXPECT_NE(message.find("set 0, binding 0"), std::string::npos) << message;
}

}  // namespace
}  // namespace lagoon::vk
