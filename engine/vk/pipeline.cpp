#include "vk/pipeline.h"

#include <algorithm>
#include <map>

#include "vk/check.h"
#include "vk/context.h"
#include "vk/spirv_reflect.h"

namespace lagoon::vk {
namespace {

ShaderReflection reflect_or_throw(const ShaderCode& code) {
  auto r = reflect_spirv(code.spirv);
  if (!r) throw_usage_error("shader " + std::string(code.name) + ": " + r.error().message);
  return std::move(r).value();
}

// Merges the stages' declarations; the same binding in two stages must agree on type and count.
PipelineInterface make_interface(const Context& ctx,
                                 std::span<const std::pair<const ShaderCode*, ShaderReflection>> stages) {
  std::map<uint32_t, InterfaceBinding> merged;
  uint32_t push_size = 0;
  VkShaderStageFlags push_stages = 0;
  std::string name;
  for (const auto& [code, refl] : stages) {
    if (!name.empty()) name += '+';
    name += code->name;
    for (const ReflectedBinding& b : refl.bindings) {
      if (b.set != 0)
        throw_usage_error("shader " + std::string(code->name) + ": binding " + std::to_string(b.binding) +
                          " is in set " + std::to_string(b.set) + "; Lagoon passes use set 0 only");
      auto [it, inserted] =
          merged.try_emplace(b.binding, InterfaceBinding{b.binding, b.type, b.count, 0, b.name});
      if (!inserted && (it->second.type != b.type || it->second.count != b.count))
        throw_usage_error("shaders " + name + " declare binding " + std::to_string(b.binding) +
                          " differently");
      it->second.stages |= refl.stage;
    }
    if (refl.push_constant_size > 0) {
      push_size = std::max(push_size, refl.push_constant_size);
      push_stages |= refl.stage;
    }
  }
  std::vector<InterfaceBinding> bindings;
  for (auto& [_, b] : merged) bindings.push_back(std::move(b));
  return PipelineInterface(ctx, name, std::move(bindings), push_size, push_stages);
}

struct SpecInfo {
  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> data;
  VkSpecializationInfo info{};
  explicit SpecInfo(std::span<const SpecConstant> spec) {
    for (const SpecConstant& s : spec) {
      entries.push_back({s.id, static_cast<uint32_t>(data.size() * 4), 4});
      data.push_back(s.value);
    }
    info = {static_cast<uint32_t>(entries.size()), entries.data(), data.size() * 4, data.data()};
  }
  const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};

Unique<VkShaderModule> make_module(const Context& ctx, const ShaderCode& code) {
  const VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                      .codeSize = code.spirv.size_bytes(),
                                      .pCode = code.spirv.data()};
  VkShaderModule module;
  VK_CHECK(vkCreateShaderModule(ctx.device(), &info, nullptr, &module));
  return {ctx.device(), module};
}

bool compatible(VkDescriptorType type, const Binding& b) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return std::holds_alternative<BufferRef>(b.resource);
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER:
    case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER:
      return std::holds_alternative<TexelBufferRef>(b.resource);
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
    case VK_DESCRIPTOR_TYPE_SAMPLER:
      return std::holds_alternative<ImageRef>(b.resource) &&
             std::get<ImageRef>(b.resource).sampler != VK_NULL_HANDLE;
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
      return std::holds_alternative<ImageRef>(b.resource);
    default:
      return false;
  }
}

// The given bindings in (binding, array element) order, so the elements of one binding lie next to each
// other and duplicates are neighbours.
std::vector<const Binding*> sorted_by_slot(std::span<const Binding> bindings) {
  std::vector<const Binding*> order;
  for (const Binding& b : bindings) order.push_back(&b);
  std::stable_sort(order.begin(), order.end(), [](const Binding* a, const Binding* b) {
    return std::pair(a->binding, a->array_element) < std::pair(b->binding, b->array_element);
  });
  return order;
}

// The shaders' declaration of `order[i]`, after checking that it exists, takes that kind of resource and is
// not given twice (`order` as sorted_by_slot returns it).
const InterfaceBinding& checked_declaration(const std::string& pass,
                                            std::span<const InterfaceBinding> declared,
                                            std::span<const Binding* const> order, size_t i) {
  const Binding& b = *order[i];
  auto it =
      std::find_if(declared.begin(), declared.end(), [&](const auto& d) { return d.binding == b.binding; });
  if (it == declared.end() || b.array_element >= it->count)
    throw_usage_error("pass " + pass + ": binding " + std::to_string(b.binding) + "[" +
                      std::to_string(b.array_element) + "] is not declared by the shaders");
  if (!compatible(it->type, b))
    throw_usage_error("pass " + pass + ": binding " + std::to_string(b.binding) + " (" + it->name +
                      ") is given a resource of the wrong kind for descriptor type " +
                      std::to_string(it->type));
  if (i > 0 && order[i - 1]->binding == b.binding && order[i - 1]->array_element == b.array_element)
    throw_usage_error("pass " + pass + ": binding " + std::to_string(b.binding) + "[" +
                      std::to_string(b.array_element) + "] is given twice");
  return *it;
}

// Push-descriptor writes with the infos they point at. One write per run of consecutive array elements
// (elements 0..n-1 of a binding in one write, with dstArrayElement 0). Mesa 22.3's lavapipe applies
// push-descriptor writes with dstArrayElement > 0 to element 0 and leaves the rest unbound, so sampler arrays
// written element by element lost every element but the first there (issue 10: the second and third ocean
// cascades vanished on lavapipe only).
class DescriptorWrites {
 public:
  // The info vectors never reallocate (writes point into them): `capacity` is the number of bindings.
  explicit DescriptorWrites(size_t capacity) {
    buffers_.reserve(capacity);
    images_.reserve(capacity);
    texel_views_.reserve(capacity);
  }

  // Bindings must come in (binding, array element) order.
  void add(const Binding& b, VkDescriptorType type) {
    const bool continues = !writes_.empty() && writes_.back().dstBinding == b.binding &&
                           writes_.back().dstArrayElement + writes_.back().descriptorCount == b.array_element;
    VkWriteDescriptorSet w{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                           .dstBinding = b.binding,
                           .dstArrayElement = b.array_element,
                           .descriptorCount = 1,
                           .descriptorType = type};
    if (const auto* buf = std::get_if<BufferRef>(&b.resource)) {
      buffers_.push_back({buf->buffer, buf->offset, buf->range});
      w.pBufferInfo = &buffers_.back();
    } else if (const auto* img = std::get_if<ImageRef>(&b.resource)) {
      images_.push_back({img->sampler, img->view, img->layout});
      w.pImageInfo = &images_.back();
    } else {
      texel_views_.push_back(std::get<TexelBufferRef>(b.resource).view);
      w.pTexelBufferView = &texel_views_.back();
    }
    if (continues)
      ++writes_.back().descriptorCount;  // the infos of one write lie next to each other in their vector
    else
      writes_.push_back(w);
  }

  const std::vector<VkWriteDescriptorSet>& writes() const { return writes_; }

 private:
  std::vector<VkWriteDescriptorSet> writes_;
  std::vector<VkDescriptorBufferInfo> buffers_;
  std::vector<VkDescriptorImageInfo> images_;
  std::vector<VkBufferView> texel_views_;
};

VkPipelineShaderStageCreateInfo shader_stage(VkShaderStageFlagBits stage, VkShaderModule module,
                                             const ShaderReflection& reflection, const SpecInfo& spec) {
  return {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
          .stage = stage,
          .module = module,
          .pName = reflection.entry_point.c_str(),
          .pSpecializationInfo = spec.get()};
}

// Straight alpha ("over") when the pass blends; otherwise colour is written as is.
VkPipelineColorBlendAttachmentState blend_attachment(const GraphicsDesc& desc) {
  return {.blendEnable = desc.alpha_blend,
          .srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA,
          .dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
          .colorBlendOp = VK_BLEND_OP_ADD,
          .srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE,
          .dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
          .alphaBlendOp = VK_BLEND_OP_ADD,
          .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                            VK_COLOR_COMPONENT_A_BIT};
}

// The fixed-function state `desc` selects, for dynamic rendering into its formats; viewport and scissor
// are dynamic, and there is no vertex input (vertex pulling).
VkPipeline create_graphics_pipeline(const Context& ctx, const GraphicsDesc& desc,
                                    std::span<const VkPipelineShaderStageCreateInfo> stages,
                                    VkPipelineLayout layout) {
  const VkPipelineVertexInputStateCreateInfo vertex_input{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  const VkPipelineInputAssemblyStateCreateInfo assembly{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO, .topology = desc.topology};
  const VkPipelineViewportStateCreateInfo viewport{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO, .viewportCount = 1, .scissorCount = 1};
  const VkPipelineRasterizationStateCreateInfo raster{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
      .polygonMode = VK_POLYGON_MODE_FILL,
      .cullMode = desc.cull,
      .frontFace = desc.front_face,
      .lineWidth = 1.0f};
  const VkPipelineMultisampleStateCreateInfo multisample{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
      .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
  const VkPipelineDepthStencilStateCreateInfo depth{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
      .depthTestEnable = desc.depth_test,
      .depthWriteEnable = desc.depth_write,
      .depthCompareOp = desc.depth_compare};
  const std::vector<VkPipelineColorBlendAttachmentState> blends(desc.color_formats.size(),
                                                                blend_attachment(desc));
  const VkPipelineColorBlendStateCreateInfo blend{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
      .attachmentCount = static_cast<uint32_t>(blends.size()),
      .pAttachments = blends.data()};
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  const VkPipelineDynamicStateCreateInfo dynamic{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
      .dynamicStateCount = 2,
      .pDynamicStates = dynamic_states};
  const VkPipelineRenderingCreateInfo rendering{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
      .colorAttachmentCount = static_cast<uint32_t>(desc.color_formats.size()),
      .pColorAttachmentFormats = desc.color_formats.data(),
      .depthAttachmentFormat = desc.depth_format};
  const VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                          .pNext = &rendering,
                                          .stageCount = static_cast<uint32_t>(stages.size()),
                                          .pStages = stages.data(),
                                          .pVertexInputState = &vertex_input,
                                          .pInputAssemblyState = &assembly,
                                          .pViewportState = &viewport,
                                          .pRasterizationState = &raster,
                                          .pMultisampleState = &multisample,
                                          .pDepthStencilState = &depth,
                                          .pColorBlendState = &blend,
                                          .pDynamicState = &dynamic,
                                          .layout = layout};
  VkPipeline pipeline;
  VK_CHECK(vkCreateGraphicsPipelines(ctx.device(), ctx.pipeline_cache(), 1, &info, nullptr, &pipeline));
  return pipeline;
}

}  // namespace

PipelineInterface::PipelineInterface(const Context& ctx, std::string name,
                                     std::vector<InterfaceBinding> bindings, uint32_t push_size,
                                     VkShaderStageFlags push_stages)
    : name_(std::move(name)),
      bindings_(std::move(bindings)),
      push_size_(push_size),
      push_stages_(push_stages) {
  std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
  for (const InterfaceBinding& b : bindings_)
    layout_bindings.push_back(
        {.binding = b.binding, .descriptorType = b.type, .descriptorCount = b.count, .stageFlags = b.stages});
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR,
      .bindingCount = static_cast<uint32_t>(layout_bindings.size()),
      .pBindings = layout_bindings.data()};
  VkDescriptorSetLayout set_layout;
  VK_CHECK(vkCreateDescriptorSetLayout(ctx.device(), &set_info, nullptr, &set_layout));
  set_layout_ = Unique<VkDescriptorSetLayout>(ctx.device(), set_layout);
  push_descriptors_ = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(ctx.device(), "vkCmdPushDescriptorSetKHR"));

  const VkPushConstantRange range{.stageFlags = push_stages_, .offset = 0, .size = push_size_};
  const VkPipelineLayoutCreateInfo layout_info{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                               .setLayoutCount = 1,
                                               .pSetLayouts = &set_layout,
                                               .pushConstantRangeCount = push_size_ > 0 ? 1u : 0u,
                                               .pPushConstantRanges = &range};
  VkPipelineLayout layout;
  VK_CHECK(vkCreatePipelineLayout(ctx.device(), &layout_info, nullptr, &layout));
  layout_ = Unique<VkPipelineLayout>(ctx.device(), layout);
}

void PipelineInterface::bind(VkCommandBuffer cmd, VkPipelineBindPoint point,
                             std::span<const Binding> bindings, const void* push, size_t push_size) const {
  // Shader blocks end at their last member; C++ structs may round up to 16 bytes. Anything else is a bug.
  if (push_size < push_size_ || push_size > ((push_size_ + 15u) & ~15u))
    throw_usage_error("pass " + name_ + ": push constants are " + std::to_string(push_size) +
                      " bytes in C++ but " + std::to_string(push_size_) + " in the shader");
  size_t expected = 0;
  for (const InterfaceBinding& b : bindings_) expected += b.count;
  if (bindings.size() != expected)
    throw_usage_error("pass " + name_ + ": " + std::to_string(bindings.size()) +
                      " bindings given, the shaders declare " + std::to_string(expected));

  const std::vector<const Binding*> order = sorted_by_slot(bindings);
  DescriptorWrites writes(bindings.size());
  for (size_t i = 0; i < order.size(); ++i)
    writes.add(*order[i], checked_declaration(name_, bindings_, order, i).type);
  if (!writes.writes().empty())
    push_descriptors_(cmd, point, layout_, 0, static_cast<uint32_t>(writes.writes().size()),
                      writes.writes().data());
  if (push_size_ > 0) vkCmdPushConstants(cmd, layout_, push_stages_, 0, push_size_, push);
}

DeferredPipeline::DeferredPipeline(VkDevice device, std::function<VkPipeline()> make, std::string key,
                                   PipelineRegistry* registry)
    : recipe_(std::make_shared<PipelineRecipe>()) {
  recipe_->device = device;
  recipe_->key = std::move(key);
  recipe_->make = std::move(make);
  recipe_->registry = registry;
  if (registry) registry->add(recipe_);
}

void DeferredPipeline::release() {
  if (!recipe_) return;
  {
    std::lock_guard lock(recipe_->mutex);  // a making on another thread finishes first
    recipe_->make = nullptr;
  }
  recipe_.reset();
}

DeferredPipeline::~DeferredPipeline() {
  release();
}

DeferredPipeline& DeferredPipeline::operator=(DeferredPipeline&& other) {
  if (this != &other) {
    release();
    recipe_ = std::move(other.recipe_);
  }
  return *this;
}

VkPipeline DeferredPipeline::get() const {
  return recipe_->use();
}

namespace {

std::string spec_key(std::span<const SpecConstant> spec) {
  std::string key;
  for (const SpecConstant& s : spec) key += " " + std::to_string(s.id) + "=" + std::to_string(s.value);
  return key;
}

// Everything create_graphics_pipeline reads from the description.
std::string graphics_key(const GraphicsDesc& d) {
  std::string key = "graphics " + std::string(d.vertex->name) + " " + std::string(d.fragment->name);
  for (VkFormat f : d.color_formats) key += " colour " + std::to_string(int(f));
  key += " depth " + std::to_string(int(d.depth_format)) + " topology " + std::to_string(int(d.topology)) +
         " cull " + std::to_string(d.cull) + " front " + std::to_string(int(d.front_face)) + " test " +
         std::to_string(d.depth_test) + " write " + std::to_string(d.depth_write) + " compare " +
         std::to_string(int(d.depth_compare)) + " blend " + std::to_string(d.alpha_blend);
  return key + spec_key(d.spec);
}

}  // namespace

ComputePipeline ComputePipeline::create(const Context& ctx, const ShaderCode& shader,
                                        std::span<const SpecConstant> spec) {
  ComputePipeline p;
  auto stage = std::make_shared<const std::pair<const ShaderCode*, ShaderReflection>>(
      &shader, reflect_or_throw(shader));
  if (stage->second.stage != VK_SHADER_STAGE_COMPUTE_BIT)
    throw_usage_error("shader " + std::string(shader.name) + " is not a compute shader");
  p.interface_ = make_interface(ctx, std::span(stage.get(), 1));
  p.local_size_ = stage->second.local_size;
  for (int axis = 0; axis < 3; ++axis)
    for (const SpecConstant& s : spec)
      if (stage->second.local_size_spec_ids[axis] == static_cast<int32_t>(s.id))
        p.local_size_[axis] = s.value;

  std::string key = "compute " + std::string(shader.name) + spec_key(spec);
  p.pipeline_ = DeferredPipeline(
      ctx.device(),
      [&ctx, stage, layout = p.interface_.layout(),
       spec = std::vector<SpecConstant>(spec.begin(), spec.end())] {
        Unique<VkShaderModule> module = make_module(ctx, *stage->first);
        const SpecInfo spec_info(spec);
        const VkComputePipelineCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
            .stage = shader_stage(VK_SHADER_STAGE_COMPUTE_BIT, module, stage->second, spec_info),
            .layout = layout};
        VkPipeline pipeline;
        VK_CHECK(vkCreateComputePipelines(ctx.device(), ctx.pipeline_cache(), 1, &info, nullptr, &pipeline));
        ctx.set_name(pipeline, VK_OBJECT_TYPE_PIPELINE, std::string(stage->first->name).c_str());
        return pipeline;
      },
      std::move(key), &ctx.pipelines());
  return p;
}

void dispatch(VkCommandBuffer cmd, const ComputePipeline& pipeline, std::span<const Binding> bindings,
              const void* push, size_t push_size, std::array<uint32_t, 3> groups) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline());
  pipeline.interface().bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bindings, push, push_size);
  vkCmdDispatch(cmd, groups[0], groups[1], groups[2]);
}

std::array<uint32_t, 3> groups_for(const ComputePipeline& pipeline, std::array<uint32_t, 3> threads) {
  std::array<uint32_t, 3> groups;
  for (int i = 0; i < 3; ++i)
    groups[i] = (threads[i] + pipeline.local_size()[i] - 1) / pipeline.local_size()[i];
  return groups;
}

GraphicsPipeline GraphicsPipeline::create(const Context& ctx, const GraphicsDesc& desc) {
  if (!desc.vertex || !desc.fragment)
    throw_usage_error("GraphicsPipeline needs a vertex and a fragment shader");
  GraphicsPipeline p;
  using Stages = std::array<std::pair<const ShaderCode*, ShaderReflection>, 2>;
  auto stages = std::make_shared<const Stages>(Stages{
      {{desc.vertex, reflect_or_throw(*desc.vertex)}, {desc.fragment, reflect_or_throw(*desc.fragment)}}});
  p.interface_ = make_interface(ctx, *stages);

  p.pipeline_ = DeferredPipeline(
      ctx.device(),
      [&ctx, stages, desc, layout = p.interface_.layout(), name = p.interface_.name()] {
        Unique<VkShaderModule> vs = make_module(ctx, *desc.vertex), fs = make_module(ctx, *desc.fragment);
        const SpecInfo spec_info(desc.spec);
        const VkPipelineShaderStageCreateInfo shader_stages[] = {
            shader_stage(VK_SHADER_STAGE_VERTEX_BIT, vs, (*stages)[0].second, spec_info),
            shader_stage(VK_SHADER_STAGE_FRAGMENT_BIT, fs, (*stages)[1].second, spec_info)};
        const VkPipeline pipeline = create_graphics_pipeline(ctx, desc, shader_stages, layout);
        ctx.set_name(pipeline, VK_OBJECT_TYPE_PIPELINE, name.c_str());
        return pipeline;
      },
      graphics_key(desc), &ctx.pipelines());
  return p;
}

void draw(VkCommandBuffer cmd, const GraphicsPipeline& pipeline, std::span<const Binding> bindings,
          const void* push, size_t push_size, uint32_t vertex_count, uint32_t instance_count) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline());
  pipeline.interface().bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bindings, push, push_size);
  vkCmdDraw(cmd, vertex_count, instance_count, 0, 0);
}

void draw_indexed(VkCommandBuffer cmd, const GraphicsPipeline& pipeline, std::span<const Binding> bindings,
                  VkBuffer index_buffer, uint32_t index_count) {
  if (index_count == 0) return;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline());
  pipeline.interface().bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bindings, nullptr, 0);
  vkCmdBindIndexBuffer(cmd, index_buffer, 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, index_count, 1, 0, 0, 0);
}

}  // namespace lagoon::vk
