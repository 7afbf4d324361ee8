// Collects what the validation layer reports. Errors and validation-type warnings (correctness) count as
// failures; performance hints do not. Tests and `LAGOON_VALIDATION=1` runs fail when failures() > 0.
#pragma once
#include <vulkan/vulkan.h>

#include <atomic>
#include <mutex>
#include <string>
#include <vector>

namespace lagoon::vk {

class ValidationLog {
 public:
  void report(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT type,
              const char* message);
  uint32_t failures() const { return failures_.load(); }
  std::vector<std::string> messages() const;  // first few failure messages, for test output
  void set_echo(bool echo) { echo_ = echo; }  // print to stderr as they arrive (default on)

  static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT type,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* user);

 private:
  std::atomic<uint32_t> failures_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
  bool echo_ = true;
};

}  // namespace lagoon::vk
