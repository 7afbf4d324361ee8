#include "vk/check.h"

#include <string>

namespace lagoon::vk {

const char* result_string(VkResult result) {
  switch (result) {
#define LAGOON_CASE(x) \
  case x:              \
    return #x;
    LAGOON_CASE(VK_SUCCESS)
    LAGOON_CASE(VK_NOT_READY)
    LAGOON_CASE(VK_TIMEOUT)
    LAGOON_CASE(VK_EVENT_SET)
    LAGOON_CASE(VK_EVENT_RESET)
    LAGOON_CASE(VK_INCOMPLETE)
    LAGOON_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    LAGOON_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    LAGOON_CASE(VK_ERROR_INITIALIZATION_FAILED)
    LAGOON_CASE(VK_ERROR_DEVICE_LOST)
    LAGOON_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    LAGOON_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    LAGOON_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    LAGOON_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    LAGOON_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    LAGOON_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    LAGOON_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    LAGOON_CASE(VK_ERROR_FRAGMENTED_POOL)
    LAGOON_CASE(VK_ERROR_UNKNOWN)
    LAGOON_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    LAGOON_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    LAGOON_CASE(VK_ERROR_FRAGMENTATION)
    LAGOON_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    LAGOON_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    LAGOON_CASE(VK_ERROR_SURFACE_LOST_KHR)
    LAGOON_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    LAGOON_CASE(VK_SUBOPTIMAL_KHR)
    LAGOON_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    LAGOON_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef LAGOON_CASE
    default:
      return "VK_RESULT_UNKNOWN";
  }
}

void throw_vulkan_error(VkResult result, const char* call, const char* file, int line) {
  throw VulkanError(std::string(call) + " failed with " + result_string(result) + " at " + file + ":" +
                        std::to_string(line),
                    result);
}

void throw_usage_error(const std::string& message) {
  throw std::logic_error("lagoon: " + message);
}

}  // namespace lagoon::vk
