#include "vk/memory.h"

#include <cstdio>

#include "vk/check.h"
#include "vk/context.h"

namespace lagoon::vk {

std::string format_mib(VkDeviceSize bytes) {
  char text[32];
  if (bytes >= (VkDeviceSize{1} << 30))
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1u << 30));
  else
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1u << 20));
  return text;
}

VkDeviceMemory allocate_memory(const Context& ctx, const VkMemoryAllocateInfo& info,
                               const std::string& what) {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  const VkResult result = vkAllocateMemory(ctx.device(), &info, nullptr, &memory);
  if (result == VK_SUCCESS) return memory;
  const VkPhysicalDeviceMemoryProperties& props = ctx.memory_properties();
  const uint32_t heap = props.memoryTypes[info.memoryTypeIndex].heapIndex;
  const char* kind = result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "out of device memory"
                     : result == VK_ERROR_OUT_OF_HOST_MEMORY ? "out of host memory"
                                                             : "cannot allocate memory";
  throw VulkanError(std::string(kind) + " allocating " + format_mib(info.allocationSize) + " for " + what +
                        " (memory heap " + std::to_string(heap) + " holds " +
                        format_mib(props.memoryHeaps[heap].size) + "; " + result_string(result) + ")",
                    result);
}

}  // namespace lagoon::vk
