// VK_CHECK: always on (also in Release). A failing call throws lagoon::vk::VulkanError naming the call,
// the VkResult and file:line; apps catch it at the top level, print it and exit non-zero.
#pragma once
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace lagoon::vk {

class VulkanError : public std::runtime_error {
 public:
  VulkanError(std::string message, VkResult result)
      : std::runtime_error(std::move(message)), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

const char* result_string(VkResult result);

[[noreturn]] void throw_vulkan_error(VkResult result, const char* call, const char* file, int line);

// Usage errors inside the engine (wrong binding type, push-constant size mismatch...): also always on.
[[noreturn]] void throw_usage_error(const std::string& message);

}  // namespace lagoon::vk

#define VK_CHECK(call)                                                                      \
  do {                                                                                      \
    VkResult lagoon_vk_check_result_ = (call);                                              \
    if (lagoon_vk_check_result_ < 0)                                                        \
      ::lagoon::vk::throw_vulkan_error(lagoon_vk_check_result_, #call, __FILE__, __LINE__); \
  } while (0)
