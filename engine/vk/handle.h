// Move-only owners for Vulkan objects. Unique<VkBuffer> etc. destroy themselves with the device that made
// them; DestroyTraits maps each handle type to its vkDestroy*/vkFree* function once, here.
#pragma once
#include <vulkan/vulkan.h>

#include <utility>

namespace lagoon::vk {

template <typename T>
struct DestroyTraits;

#define LAGOON_DESTROY_TRAIT(Type, fn)                                                 \
  template <>                                                                          \
  struct DestroyTraits<Type> {                                                         \
    static void destroy(VkDevice device, Type handle) { fn(device, handle, nullptr); } \
  };
LAGOON_DESTROY_TRAIT(VkBuffer, vkDestroyBuffer)
LAGOON_DESTROY_TRAIT(VkImage, vkDestroyImage)
LAGOON_DESTROY_TRAIT(VkImageView, vkDestroyImageView)
LAGOON_DESTROY_TRAIT(VkSampler, vkDestroySampler)
LAGOON_DESTROY_TRAIT(VkDeviceMemory, vkFreeMemory)
LAGOON_DESTROY_TRAIT(VkShaderModule, vkDestroyShaderModule)
LAGOON_DESTROY_TRAIT(VkPipeline, vkDestroyPipeline)
LAGOON_DESTROY_TRAIT(VkPipelineLayout, vkDestroyPipelineLayout)
LAGOON_DESTROY_TRAIT(VkPipelineCache, vkDestroyPipelineCache)
LAGOON_DESTROY_TRAIT(VkDescriptorSetLayout, vkDestroyDescriptorSetLayout)
LAGOON_DESTROY_TRAIT(VkDescriptorPool, vkDestroyDescriptorPool)
LAGOON_DESTROY_TRAIT(VkCommandPool, vkDestroyCommandPool)
LAGOON_DESTROY_TRAIT(VkFence, vkDestroyFence)
LAGOON_DESTROY_TRAIT(VkSemaphore, vkDestroySemaphore)
LAGOON_DESTROY_TRAIT(VkQueryPool, vkDestroyQueryPool)
LAGOON_DESTROY_TRAIT(VkSwapchainKHR, vkDestroySwapchainKHR)
LAGOON_DESTROY_TRAIT(VkRenderPass, vkDestroyRenderPass)
LAGOON_DESTROY_TRAIT(VkFramebuffer, vkDestroyFramebuffer)
#undef LAGOON_DESTROY_TRAIT

template <typename T>
class Unique {
 public:
  Unique() = default;
  Unique(VkDevice device, T handle) : device_(device), handle_(handle) {}
  Unique(const Unique&) = delete;
  Unique& operator=(const Unique&) = delete;
  Unique(Unique&& other) noexcept
      : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
        handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  Unique& operator=(Unique&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = std::exchange(other.device_, VK_NULL_HANDLE);
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }
  ~Unique() { reset(); }

  T get() const { return handle_; }
  operator T() const { return handle_; }  // NOLINT: pass straight to vkCmd* calls
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
  VkDevice device() const { return device_; }

  void reset() {
    if (handle_ != VK_NULL_HANDLE) DestroyTraits<T>::destroy(device_, handle_);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  T handle_ = VK_NULL_HANDLE;
};

}  // namespace lagoon::vk
