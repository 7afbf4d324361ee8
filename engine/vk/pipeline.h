// Compute and graphics pipelines from embedded SPIR-V. The descriptor-set layout (set 0, push descriptors)
// and the push-constant range are derived from SPIR-V reflection, so a new pass is: one shader, one
// ComputePipeline::create, one dispatch() with its bindings and push constants. Mismatches between what the
// C++ side binds and what the shader declares throw with the shader's name and binding number.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <initializer_list>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "vk/buffer.h"
#include "vk/handle.h"
#include "vk/pipeline_recipe.h"
#include "vk/pipeline_registry.h"
#include "vk/shader_code.h"

namespace lagoon::vk {

class Context;

struct SpecConstant {
  uint32_t id = 0;
  uint32_t value = 0;  // bit pattern: use std::bit_cast<uint32_t>(1.5f) for floats
};

struct BufferRef {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize range = VK_WHOLE_SIZE;
};
struct ImageRef {
  VkImageView view = VK_NULL_HANDLE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;
  VkSampler sampler = VK_NULL_HANDLE;  // for combined image samplers and plain samplers
};
struct TexelBufferRef {
  VkBufferView view = VK_NULL_HANDLE;
};

struct Binding {
  uint32_t binding = 0;
  std::variant<BufferRef, ImageRef, TexelBufferRef> resource;
  uint32_t array_element = 0;
};

inline Binding bind(uint32_t binding, const Buffer& buffer) {
  return {binding, BufferRef{buffer.handle()}};
}
inline Binding bind(uint32_t binding, BufferRef buffer) {
  return {binding, buffer};
}
inline Binding bind(uint32_t binding, ImageRef image, uint32_t array_element = 0) {
  return {binding, image, array_element};
}
inline Binding bind(uint32_t binding, TexelBufferRef texels) {
  return {binding, texels};
}

struct InterfaceBinding {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t count = 1;
  VkShaderStageFlags stages = 0;
  std::string name;
};

// What a pipeline's shaders expect: descriptor set 0 (as push descriptors) and push constants.
class PipelineInterface {
 public:
  PipelineInterface() = default;
  PipelineInterface(const Context& ctx, std::string name, std::vector<InterfaceBinding> bindings,
                    uint32_t push_size, VkShaderStageFlags push_stages);

  VkPipelineLayout layout() const { return layout_; }
  const std::vector<InterfaceBinding>& bindings() const { return bindings_; }
  uint32_t push_constant_size() const { return push_size_; }
  const std::string& name() const { return name_; }

  // Pushes the descriptors and constants. Every declared binding must be given exactly once, with a
  // resource of the matching kind; `push_size` must cover the shader's block (C++ structs may add tail
  // padding).
  void bind(VkCommandBuffer cmd, VkPipelineBindPoint point, std::span<const Binding> bindings,
            const void* push, size_t push_size) const;

 private:
  std::string name_;
  std::vector<InterfaceBinding> bindings_;
  uint32_t push_size_ = 0;
  VkShaderStageFlags push_stages_ = 0;
  PFN_vkCmdPushDescriptorSetKHR push_descriptors_ = nullptr;  // extension entry point, loaded per device
  Unique<VkDescriptorSetLayout> set_layout_;
  Unique<VkPipelineLayout> layout_;
};

// A VkPipeline made on first use: creating a renderer's passes compiles nothing for the pipelines its scene
// never draws with (the underwater ones above the water, the waterline's, the classic shading modes), and
// on lavapipe a pipeline's creation alone costs tens of milliseconds. get() is thread-safe (a lock), as a
// made pipeline was to read from several threads.
class DeferredPipeline {
 public:
  DeferredPipeline() = default;
  // Declared in `registry` (when given) under `key` (vk/pipeline_recipe.h), so another thread may make it
  // ahead of its first use (vk/pipeline_warmer.h).
  DeferredPipeline(VkDevice device, std::function<VkPipeline()> make, std::string key,
                   PipelineRegistry* registry);
  // Waits for a making of it on another thread to finish (what the recipe captured, e.g. the layout, must
  // outlive that).
  ~DeferredPipeline();
  DeferredPipeline(DeferredPipeline&&) = default;
  DeferredPipeline& operator=(DeferredPipeline&& other);
  VkPipeline get() const;
  bool empty() const { return !recipe_; }

 private:
  void release();
  std::shared_ptr<PipelineRecipe> recipe_;
};

class ComputePipeline {
 public:
  ComputePipeline() = default;
  // Reflects the shader and makes its layout now; the pipeline itself on first use.
  static ComputePipeline create(const Context& ctx, const ShaderCode& shader,
                                std::span<const SpecConstant> spec = {});

  // Made here on the first call (VK_NULL_HANDLE for a default-constructed one).
  VkPipeline pipeline() const { return pipeline_.empty() ? VK_NULL_HANDLE : pipeline_.get(); }
  bool empty() const { return pipeline_.empty(); }
  const PipelineInterface& interface() const { return interface_; }
  // Workgroup size, with specialisation constants applied.
  const std::array<uint32_t, 3>& local_size() const { return local_size_; }

 private:
  PipelineInterface interface_;
  DeferredPipeline pipeline_;
  std::array<uint32_t, 3> local_size_{1, 1, 1};
};

// Records one compute dispatch: binds the pipeline, pushes descriptors and constants.
void dispatch(VkCommandBuffer cmd, const ComputePipeline& pipeline, std::span<const Binding> bindings,
              const void* push, size_t push_size, std::array<uint32_t, 3> groups);

template <typename Push>
void dispatch(VkCommandBuffer cmd, const ComputePipeline& pipeline, std::initializer_list<Binding> bindings,
              const Push& push, std::array<uint32_t, 3> groups) {
  dispatch(cmd, pipeline, std::span<const Binding>(bindings.begin(), bindings.size()), &push, sizeof(Push),
           groups);
}
inline void dispatch(VkCommandBuffer cmd, const ComputePipeline& pipeline,
                     std::initializer_list<Binding> bindings, std::array<uint32_t, 3> groups) {
  dispatch(cmd, pipeline, std::span<const Binding>(bindings.begin(), bindings.size()), nullptr, 0, groups);
}

// Workgroups needed to cover `threads` invocations per axis.
std::array<uint32_t, 3> groups_for(const ComputePipeline& pipeline, std::array<uint32_t, 3> threads);

struct GraphicsDesc {
  const ShaderCode* vertex = nullptr;
  const ShaderCode* fragment = nullptr;
  std::vector<VkFormat> color_formats;
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  bool depth_test = false;
  bool depth_write = false;
  VkCompareOp depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL;
  bool alpha_blend = false;
  std::vector<SpecConstant> spec;
};

// Vertex data comes from storage buffers (vertex pulling), so there is no vertex-input state to declare.
class GraphicsPipeline {
 public:
  GraphicsPipeline() = default;
  // Reflects the shaders and makes the layout now; the pipeline itself on first use.
  static GraphicsPipeline create(const Context& ctx, const GraphicsDesc& desc);

  // Made here on the first call (VK_NULL_HANDLE for a default-constructed one).
  VkPipeline pipeline() const { return pipeline_.empty() ? VK_NULL_HANDLE : pipeline_.get(); }
  bool empty() const { return pipeline_.empty(); }
  const PipelineInterface& interface() const { return interface_; }

 private:
  PipelineInterface interface_;
  DeferredPipeline pipeline_;
};

void draw(VkCommandBuffer cmd, const GraphicsPipeline& pipeline, std::span<const Binding> bindings,
          const void* push, size_t push_size, uint32_t vertex_count, uint32_t instance_count = 1);

// An indexed draw (32-bit indices from `index_buffer`): unlike indices pulled from a storage buffer, the
// device's vertex cache shades a vertex that several triangles share once.
void draw_indexed(VkCommandBuffer cmd, const GraphicsPipeline& pipeline, std::span<const Binding> bindings,
                  VkBuffer index_buffer, uint32_t index_count);

template <typename Push>
void draw(VkCommandBuffer cmd, const GraphicsPipeline& pipeline, std::initializer_list<Binding> bindings,
          const Push& push, uint32_t vertex_count, uint32_t instance_count = 1) {
  draw(cmd, pipeline, std::span<const Binding>(bindings.begin(), bindings.size()), &push, sizeof(Push),
       vertex_count, instance_count);
}

inline void draw(VkCommandBuffer cmd, const GraphicsPipeline& pipeline,
                 std::initializer_list<Binding> bindings, uint32_t vertex_count,
                 uint32_t instance_count = 1) {
  draw(cmd, pipeline, std::span<const Binding>(bindings.begin(), bindings.size()), nullptr, 0, vertex_count,
       instance_count);
}

}  // namespace lagoon::vk
