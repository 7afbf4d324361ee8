#include "vk/validation.h"

#include <cstdio>

namespace lagoon::vk {

void ValidationLog::report(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                           VkDebugUtilsMessageTypeFlagsEXT type, const char* message) {
  const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  const bool correctness_warning = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) &&
                                   (type & VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT);
  if (!error && !correctness_warning) return;
  failures_.fetch_add(1);
  std::lock_guard lock(mutex_);
  if (messages_.size() < 32) messages_.emplace_back(message);
  if (echo_) std::fprintf(stderr, "[vulkan validation %s] %s\n", error ? "error" : "warning", message);
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

VkBool32 ValidationLog::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                 VkDebugUtilsMessageTypeFlagsEXT type,
                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  static_cast<ValidationLog*>(user)->report(severity, type, data->pMessage ? data->pMessage : "");
  return VK_FALSE;
}

}  // namespace lagoon::vk
