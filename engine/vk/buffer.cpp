#include "vk/buffer.h"

#include "vk/check.h"
#include "vk/context.h"
#include "vk/memory.h"

namespace lagoon::vk {

Buffer Buffer::create(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory,
                      const char* debug_name) {
  if (size == 0) throw_usage_error(std::string("buffer '") + (debug_name ? debug_name : "") + "' has size 0");
  Buffer b;
  b.size_ = size;
  const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                .size = size,
                                .usage = usage,
                                .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
  VkBuffer buffer;
  VK_CHECK(vkCreateBuffer(ctx.device(), &info, nullptr, &buffer));
  b.buffer_ = Unique<VkBuffer>(ctx.device(), buffer);
  ctx.set_name(buffer, VK_OBJECT_TYPE_BUFFER, debug_name);

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device(), buffer, &req);
  VkMemoryPropertyFlags required = 0, preferred = 0;
  switch (memory) {
    case MemoryUsage::Device:
      preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
      break;
    case MemoryUsage::Upload:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case MemoryUsage::Readback:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
      preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  const uint32_t type = ctx.find_memory_type(req.memoryTypeBits, required, preferred);
  const VkMemoryAllocateInfo alloc{
      .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size, .memoryTypeIndex = type};
  VkDeviceMemory mem =
      allocate_memory(ctx, alloc, "buffer " + std::string(debug_name ? debug_name : "(unnamed)"));
  b.memory_ = Unique<VkDeviceMemory>(ctx.device(), mem);
  VK_CHECK(vkBindBufferMemory(ctx.device(), buffer, mem, 0));

  const VkMemoryPropertyFlags flags = ctx.memory_properties().memoryTypes[type].propertyFlags;
  b.coherent_ = flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  if (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
    VK_CHECK(vkMapMemory(ctx.device(), mem, 0, VK_WHOLE_SIZE, 0, &b.mapped_));
  return b;
}

void Buffer::invalidate() const {
  if (coherent_ || !mapped_) return;
  const VkMappedMemoryRange range{
      .sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, .memory = memory_, .size = VK_WHOLE_SIZE};
  VK_CHECK(vkInvalidateMappedMemoryRanges(memory_.device(), 1, &range));
}

void Buffer::flush() const {
  if (coherent_ || !mapped_) return;
  const VkMappedMemoryRange range{
      .sType = VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, .memory = memory_, .size = VK_WHOLE_SIZE};
  VK_CHECK(vkFlushMappedMemoryRanges(memory_.device(), 1, &range));
}

}  // namespace lagoon::vk
