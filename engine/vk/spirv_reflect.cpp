#include "vk/spirv_reflect.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <unordered_map>
#include <utility>

namespace lagoon::vk {
namespace {

// SPIR-V enumerant values from the unified spec, spelled out so the engine does not depend on whichever
// spirv.hpp the system ships. Only what reflection needs.
constexpr uint32_t kMagic = 0x07230203;
constexpr uint32_t kMagicSwapped = 0x03022307;  // a big-endian module read on a little-endian host
constexpr size_t kHeaderWords = 5;

// Opcodes.
constexpr uint32_t kOpName = 5, kOpEntryPoint = 15, kOpExecutionMode = 16, kOpTypeInt = 21, kOpTypeFloat = 22,
                   kOpTypeVector = 23, kOpTypeMatrix = 24, kOpTypeImage = 25, kOpTypeSampler = 26,
                   kOpTypeSampledImage = 27, kOpTypeArray = 28, kOpTypeRuntimeArray = 29, kOpTypeStruct = 30,
                   kOpTypePointer = 32, kOpConstant = 43, kOpConstantComposite = 44, kOpSpecConstant = 50,
                   kOpSpecConstantComposite = 51, kOpVariable = 59, kOpDecorate = 71, kOpMemberDecorate = 72,
                   kOpExecutionModeId = 331, kOpTypeAccelerationStructure = 5341;
// Decorations.
constexpr uint32_t kSpecId = 1, kBlock = 2, kBufferBlock = 3, kRowMajor = 4, kArrayStride = 6,
                   kMatrixStride = 7, kBuiltIn = 11, kBinding = 33, kDescriptorSet = 34, kOffset = 35;
// Storage classes.
constexpr uint32_t kUniformConstant = 0, kUniform = 2, kPushConstant = 9, kStorageBuffer = 12,
                   kPhysicalStorageBuffer = 5349;
constexpr uint32_t kLocalSize = 17, kLocalSizeId = 38;  // execution modes
constexpr uint32_t kBuiltInWorkgroupSize = 25;
constexpr uint32_t kDimBuffer = 5, kDimSubpassData = 6;
constexpr uint32_t kMaxStructMembers = 16383;  // SPIR-V universal limit; bounds allocations on bad input
constexpr int kMaxTypeDepth = 64;              // real types nest a few levels; guards against cycles

using Instruction = std::span<const uint32_t>;  // one instruction, opcode word first
uint32_t opcode(Instruction inst) {
  return inst[0] & 0xffffu;
}

// Words needed before the fields read below may be indexed; shorter instructions are rejected.
constexpr std::pair<uint32_t, size_t> kMinWords[] = {
    {kOpName, 3},      {kOpDecorate, 3},         {kOpExecutionMode, 3},    {kOpExecutionModeId, 3},
    {kOpTypeFloat, 3}, {kOpTypeSampledImage, 3}, {kOpTypeRuntimeArray, 3}, {kOpEntryPoint, 4},
    {kOpTypeInt, 4},   {kOpMemberDecorate, 4},   {kOpTypeVector, 4},       {kOpTypeMatrix, 4},
    {kOpTypeArray, 4}, {kOpTypePointer, 4},      {kOpConstant, 4},         {kOpSpecConstant, 4},
    {kOpVariable, 4},  {kOpTypeImage, 9}};
bool is_type(uint32_t op) {
  return (op >= 19 && op <= 38) || op == kOpTypeAccelerationStructure;
}
// Constants have their result id at [2], after the result type; types at [1].
bool is_constant(uint32_t op) {
  return op >= 41 && op <= 52;
}
size_t min_words(uint32_t op) {
  for (auto [code, words] : kMinWords) {
    if (code == op) return words;
  }
  return is_constant(op) ? 3 : is_type(op) ? 2 : 1;  // enough to read the result id
}

// Literal strings are UTF-8 packed little-end first into words, NUL-terminated.
std::string decode_string(std::span<const uint32_t> words) {
  std::string s;
  for (uint32_t w : words) {
    for (int i = 0; i < 4; ++i) {
      const char c = static_cast<char>((w >> (8 * i)) & 0xffu);
      if (c == '\0') return s;
      s += c;
    }
  }
  return s;
}

std::string hex(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", v);
  return buf;
}

std::optional<uint32_t> literal(Instruction inst, size_t i) {
  return i < inst.size() ? std::optional(inst[i]) : std::nullopt;
}

constexpr std::pair<uint32_t, VkShaderStageFlagBits> kStages[] = {  // execution model -> stage
    {0, VK_SHADER_STAGE_VERTEX_BIT},
    {1, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT},
    {2, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT},
    {3, VK_SHADER_STAGE_GEOMETRY_BIT},
    {4, VK_SHADER_STAGE_FRAGMENT_BIT},
    {5, VK_SHADER_STAGE_COMPUTE_BIT},
    {5313, VK_SHADER_STAGE_RAYGEN_BIT_KHR},
    {5314, VK_SHADER_STAGE_INTERSECTION_BIT_KHR},
    {5315, VK_SHADER_STAGE_ANY_HIT_BIT_KHR},
    {5316, VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR},
    {5317, VK_SHADER_STAGE_MISS_BIT_KHR},
    {5318, VK_SHADER_STAGE_CALLABLE_BIT_KHR},
    {5364, VK_SHADER_STAGE_TASK_BIT_EXT},
    {5365, VK_SHADER_STAGE_MESH_BIT_EXT}};
std::optional<VkShaderStageFlagBits> stage_of(uint32_t execution_model) {
  for (auto [model, stage] : kStages) {
    if (model == execution_model) return stage;
  }
  return std::nullopt;
}

struct Decorations {
  std::optional<uint32_t> set, binding, spec_id, array_stride;
  bool block = false, buffer_block = false;
};

struct MemberLayout {
  std::optional<uint32_t> offset;
  uint32_t matrix_stride = 0;
  bool row_major = false;
};

class Module {
 public:
  Result<ShaderReflection> reflect(std::span<const uint32_t> body);

 private:
  Result<void> record(Instruction inst, size_t word_index);
  Result<void> record_entry_point(Instruction inst);
  Result<void> record_execution_mode(Instruction inst);
  void record_decoration(Instruction inst);
  Result<void> record_member_decoration(Instruction inst);
  Result<void> resolve_workgroup_size();
  Result<ReflectedBinding> describe(uint32_t var, uint32_t type, uint32_t storage) const;
  Result<VkDescriptorType> descriptor_type(uint32_t type, uint32_t storage) const;
  Result<uint32_t> size_of(uint32_t type, const MemberLayout& layout, int depth) const;
  std::optional<uint32_t> constant(uint32_t id) const;
  const Instruction* def(uint32_t id) const {
    auto it = defs_.find(id);
    return it == defs_.end() ? nullptr : &it->second;
  }
  Decorations decorations(uint32_t id) const {
    auto it = decorations_.find(id);
    return it == decorations_.end() ? Decorations{} : it->second;
  }
  std::string name(uint32_t id) const {
    auto it = names_.find(id);
    return it == names_.end() ? "" : it->second;
  }

  ShaderReflection out_;
  int entry_points_ = 0;
  std::unordered_map<uint32_t, Instruction> defs_;  // result id -> defining type/constant instruction
  std::unordered_map<uint32_t, std::string> names_;
  std::unordered_map<uint32_t, Decorations> decorations_;
  std::unordered_map<uint32_t, std::vector<MemberLayout>> members_;  // struct id -> member layouts
  std::vector<Instruction> variables_;
  std::optional<std::array<uint32_t, 3>> local_size_ids_;  // from OpExecutionModeId LocalSizeId
  std::optional<uint32_t> workgroup_size_builtin_;         // composite decorated BuiltIn WorkgroupSize
};

Result<ShaderReflection> Module::reflect(std::span<const uint32_t> body) {
  for (size_t pos = 0; pos < body.size();) {
    const uint32_t count = body[pos] >> 16;
    const size_t word_index = pos + kHeaderWords;  // position in the whole module, for messages
    if (count == 0) {
      return make_error("SPIR-V module is corrupt: instruction at word " + std::to_string(word_index) +
                        " has a word count of 0");
    }
    if (count > body.size() - pos) {
      return make_error("SPIR-V module is truncated: instruction at word " + std::to_string(word_index) +
                        " needs " + std::to_string(count) + " words but only " +
                        std::to_string(body.size() - pos) + " remain");
    }
    if (auto r = record(body.subspan(pos, count), word_index); !r) return r.error();
    pos += count;
  }
  if (entry_points_ == 0) return make_error("SPIR-V module has no OpEntryPoint");
  if (auto r = resolve_workgroup_size(); !r) return r.error();

  for (Instruction var : variables_) {
    const uint32_t storage = var[3];
    if (storage != kUniformConstant && storage != kUniform && storage != kStorageBuffer &&
        storage != kPushConstant) {
      continue;
    }
    const Instruction* pointer = def(var[1]);
    if (pointer == nullptr || opcode(*pointer) != kOpTypePointer) {
      return make_error("SPIR-V variable %" + std::to_string(var[2]) + " does not have a pointer type");
    }
    const uint32_t pointee = (*pointer)[3];
    if (storage == kPushConstant) {
      auto size = size_of(pointee, {}, 0);
      if (!size) return make_error("push-constant block: " + size.error().message);
      out_.push_constant_size = std::max(out_.push_constant_size, size.value());
      continue;
    }
    auto binding = describe(var[2], pointee, storage);
    if (!binding) return binding.error();
    out_.bindings.push_back(std::move(binding).value());
  }
  std::stable_sort(out_.bindings.begin(), out_.bindings.end(), [](const auto& a, const auto& b) {
    return std::pair(a.set, a.binding) < std::pair(b.set, b.binding);
  });
  return std::move(out_);
}

// Pass 1: remember what later lookups need; nothing is interpreted until the whole module is read.
Result<void> Module::record(Instruction inst, size_t word_index) {
  const uint32_t op = opcode(inst);
  if (inst.size() < min_words(op)) {
    return make_error("SPIR-V module is corrupt: opcode " + std::to_string(op) + " at word " +
                      std::to_string(word_index) + " has too few operands");
  }
  if (is_type(op)) defs_[inst[1]] = inst;
  if (is_constant(op)) defs_[inst[2]] = inst;
  switch (op) {
    case kOpName:
      names_[inst[1]] = decode_string(inst.subspan(2));
      return {};
    case kOpEntryPoint:
      return record_entry_point(inst);
    case kOpExecutionMode:
    case kOpExecutionModeId:
      return record_execution_mode(inst);
    case kOpDecorate:
      record_decoration(inst);
      return {};
    case kOpMemberDecorate:
      return record_member_decoration(inst);
    case kOpVariable:
      variables_.push_back(inst);
      return {};
    default:
      return {};
  }
}

Result<void> Module::record_entry_point(Instruction inst) {
  const std::string entry = decode_string(inst.subspan(3));
  if (++entry_points_ > 1) {
    return make_error("SPIR-V module has more than one entry point ('" + out_.entry_point + "', '" + entry +
                      "'); only single-entry modules are supported");
  }
  const auto stage = stage_of(inst[1]);
  if (!stage) return make_error("SPIR-V execution model " + std::to_string(inst[1]) + " is not supported");
  out_.stage = *stage;
  out_.entry_point = entry;
  return {};
}

// LocalSize gives the workgroup size as literals, LocalSizeId as constant ids resolved after pass 1.
Result<void> Module::record_execution_mode(Instruction inst) {
  const uint32_t mode = inst[2];
  if (mode != kLocalSize && mode != kLocalSizeId) return {};
  if (inst.size() < 6) return make_error("SPIR-V LocalSize execution mode needs 3 operands");
  if (mode == kLocalSize) {
    out_.local_size = {inst[3], inst[4], inst[5]};
  } else {
    local_size_ids_ = {inst[3], inst[4], inst[5]};
  }
  return {};
}

void Module::record_decoration(Instruction inst) {
  Decorations& d = decorations_[inst[1]];
  const uint32_t decoration = inst[2];
  if (decoration == kBlock) d.block = true;
  if (decoration == kBufferBlock) d.buffer_block = true;
  if (decoration == kDescriptorSet) d.set = literal(inst, 3);
  if (decoration == kBinding) d.binding = literal(inst, 3);
  if (decoration == kSpecId) d.spec_id = literal(inst, 3);
  if (decoration == kArrayStride) d.array_stride = literal(inst, 3);
  if (decoration == kBuiltIn && literal(inst, 3) == kBuiltInWorkgroupSize) workgroup_size_builtin_ = inst[1];
}

Result<void> Module::record_member_decoration(Instruction inst) {
  const uint32_t member = inst[2];
  if (member >= kMaxStructMembers) return make_error("SPIR-V OpMemberDecorate member index is out of range");
  std::vector<MemberLayout>& layouts = members_[inst[1]];
  if (layouts.size() <= member) layouts.resize(member + 1);
  MemberLayout& m = layouts[member];
  if (inst[3] == kOffset) m.offset = literal(inst, 4);
  if (inst[3] == kMatrixStride) m.matrix_stride = literal(inst, 4).value_or(0);
  if (inst[3] == kRowMajor) m.row_major = true;
  return {};
}

// The WorkgroupSize built-in overrides LocalSize/LocalSizeId (SPIR-V spec). glslang emits it for
// local_size_*_id before SPIR-V 1.6, and OpExecutionModeId LocalSizeId from 1.6 on.
Result<void> Module::resolve_workgroup_size() {
  std::optional<std::array<uint32_t, 3>> ids = local_size_ids_;
  if (workgroup_size_builtin_) {
    const Instruction* c = def(*workgroup_size_builtin_);
    if (c == nullptr || (opcode(*c) != kOpConstantComposite && opcode(*c) != kOpSpecConstantComposite) ||
        c->size() < 6) {
      return make_error("SPIR-V WorkgroupSize built-in is not a 3-component constant composite");
    }
    ids = {(*c)[3], (*c)[4], (*c)[5]};
  }
  if (!ids) return {};
  for (int axis = 0; axis < 3; ++axis) {
    const auto value = constant((*ids)[axis]);
    if (!value) return make_error("SPIR-V workgroup size component is not a scalar (spec) constant");
    out_.local_size[axis] = *value;
    const auto spec_id = decorations((*ids)[axis]).spec_id;
    out_.local_size_spec_ids[axis] = spec_id ? static_cast<int32_t>(*spec_id) : -1;
  }
  return {};
}

// Value (or default value, for spec constants) of a scalar integer constant.
std::optional<uint32_t> Module::constant(uint32_t id) const {
  const Instruction* c = def(id);
  if (c == nullptr || (opcode(*c) != kOpConstant && opcode(*c) != kOpSpecConstant)) return std::nullopt;
  return (*c)[3];  // low word; lengths and sizes fit in 32 bits
}

Result<ReflectedBinding> Module::describe(uint32_t var, uint32_t type, uint32_t storage) const {
  const Decorations d = decorations(var);
  ReflectedBinding b{.set = d.set.value_or(0), .binding = d.binding.value_or(0), .name = name(var)};
  const std::string where = "descriptor " +
                            (b.name.empty() ? "%" + std::to_string(var) : "'" + b.name + "'") + " (set " +
                            std::to_string(b.set) + ", binding " + std::to_string(b.binding) + ")";
  // Arrays of descriptors (also arrays of arrays, which Vulkan flattens) become the descriptor count.
  for (int depth = 0;; ++depth) {
    const Instruction* t = def(type);
    if (t == nullptr) break;
    if (depth > kMaxTypeDepth) return make_error(where + ": array type nesting is too deep");
    if (opcode(*t) == kOpTypeRuntimeArray) {
      return make_error(where + ": unsized descriptor arrays are not supported");
    }
    if (opcode(*t) != kOpTypeArray) break;
    const auto length = constant((*t)[3]);
    if (!length) return make_error(where + ": array length is not a constant");
    b.count *= *length;
    type = (*t)[2];
  }
  if (b.name.empty()) b.name = name(type);  // anonymous block instance: use the block name
  auto descriptor = descriptor_type(type, storage);
  if (!descriptor) return make_error(where + ": " + descriptor.error().message);
  b.type = descriptor.value();
  return b;
}

Result<VkDescriptorType> Module::descriptor_type(uint32_t type, uint32_t storage) const {
  const Instruction* t = def(type);
  if (t == nullptr) return make_error("type %" + std::to_string(type) + " is not defined");
  const uint32_t op = opcode(*t);
  if (storage == kStorageBuffer || storage == kUniform) {
    if (op != kOpTypeStruct) return make_error("buffer variable does not have a struct type");
    const Decorations d = decorations(type);
    // Before SPIR-V 1.3 storage buffers were Uniform + BufferBlock.
    if (storage == kStorageBuffer || d.buffer_block) return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (d.block) return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    return make_error("Uniform struct is decorated neither Block nor BufferBlock");
  }
  switch (op) {  // UniformConstant: opaque types
    case kOpTypeSampler:
      return VK_DESCRIPTOR_TYPE_SAMPLER;
    case kOpTypeSampledImage: {
      const Instruction* image = def((*t)[2]);
      if (image == nullptr || opcode(*image) != kOpTypeImage) {
        return make_error("sampled image type does not refer to an image type");
      }
      return (*image)[3] == kDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                       : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    }
    case kOpTypeImage: {
      const uint32_t dim = (*t)[3], sampled = (*t)[7];
      if (dim == kDimSubpassData) return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
      if (sampled == 1) {
        return dim == kDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
      }
      if (sampled == 2) {
        return dim == kDimBuffer ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      }
      return make_error("image with Sampled=" + std::to_string(sampled) +
                        " (not known at compile time) is not supported");
    }
    case kOpTypeAccelerationStructure:
      return make_error("acceleration structures are not supported");
    default:
      return make_error("unsupported descriptor type (SPIR-V opcode " + std::to_string(op) + ")");
  }
}

// Bytes from the start of `type` to the end of its last member, using the explicit layout decorations
// (Offset, ArrayStride, MatrixStride) that Vulkan requires on push-constant blocks.
Result<uint32_t> Module::size_of(uint32_t type, const MemberLayout& layout, int depth) const {
  const Instruction* t = def(type);
  const std::string what = "type %" + std::to_string(type);
  if (t == nullptr) return make_error(what + " is not defined");
  if (depth > kMaxTypeDepth) return make_error(what + " is nested too deeply (corrupt module?)");
  switch (opcode(*t)) {
    case kOpTypeInt:
    case kOpTypeFloat:
      return (*t)[2] / 8;
    case kOpTypeVector: {
      auto component = size_of((*t)[2], layout, depth + 1);
      if (!component) return component.error();
      return component.value() * (*t)[3];
    }
    case kOpTypeMatrix: {
      if (layout.matrix_stride == 0) return make_error("matrix " + what + " has no MatrixStride decoration");
      if (!layout.row_major) return (*t)[3] * layout.matrix_stride;  // columns * stride
      const Instruction* column = def((*t)[2]);
      if (column == nullptr || opcode(*column) != kOpTypeVector) return make_error("bad matrix " + what);
      return (*column)[3] * layout.matrix_stride;  // rows * stride
    }
    case kOpTypeArray: {
      const auto length = constant((*t)[3]);
      const auto stride = decorations(type).array_stride;
      if (!length) return make_error("array " + what + " does not have a constant length");
      if (!stride) return make_error("array " + what + " has no ArrayStride decoration");
      return *length * *stride;
    }
    case kOpTypeStruct: {
      const auto found = members_.find(type);
      uint32_t end = 0;
      for (size_t i = 0; i + 2 < t->size(); ++i) {
        if (found == members_.end() || i >= found->second.size() || !found->second[i].offset) {
          return make_error("member " + std::to_string(i) + " of struct " + what +
                            " has no Offset decoration");
        }
        const MemberLayout& member = found->second[i];
        auto size = size_of((*t)[i + 2], member, depth + 1);
        if (!size) return size.error();
        end = std::max(end, *member.offset + size.value());
      }
      return end;
    }
    case kOpTypePointer:  // buffer_reference: a 64-bit device address
      if ((*t)[2] == kPhysicalStorageBuffer) return 8u;
      [[fallthrough]];
    default:
      return make_error("unsupported " + what + " (SPIR-V opcode " + std::to_string(opcode(*t)) + ")");
  }
}

}  // namespace

Result<ShaderReflection> reflect_spirv(std::span<const uint32_t> words) {
  if (words.empty()) return make_error("SPIR-V module is empty");
  if (words.size() < kHeaderWords) {
    return make_error("SPIR-V module is too short: " + std::to_string(words.size()) +
                      " words, the header alone is 5");
  }
  if (words[0] != kMagic) {
    if (words[0] == kMagicSwapped) {
      return make_error("SPIR-V module has the wrong byte order (magic 0x03022307); expected host order");
    }
    return make_error("not a SPIR-V module: bad magic number " + hex(words[0]) + " (expected 0x07230203)");
  }
  Module module;
  return module.reflect(words.subspan(kHeaderWords));
}

}  // namespace lagoon::vk
