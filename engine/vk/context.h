// The Vulkan context: instance, validation, the chosen device and its one graphics+compute queue,
// pipeline cache, deferred destruction and one-shot submission. Headless by default; give
// ContextOptions::create_surface (and the window's instance extensions) to also present to a window.
#pragma once
#include <vulkan/vulkan.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "vk/deferred.h"
#include "vk/handle.h"
#include "vk/result.h"
#include "vk/validation.h"

namespace lagoon::vk {

struct ContextOptions {
  // Validation layer; default from LAGOON_VALIDATION=1. When on and the layer is missing, create() fails.
  bool validation = false;
  // LAGOON_DEVICE: device index or case-insensitive name substring; "" = automatic choice.
  std::string device_override;
  // Extra instance extensions, e.g. glfwGetRequiredInstanceExtensions().
  std::vector<std::string> instance_extensions;
  // When set, called once with the instance; the chosen device must present to the returned surface.
  std::function<VkSurfaceKHR(VkInstance)> create_surface;
  // Where the pipeline cache persists; empty = no persistence. Default from LAGOON_PIPELINE_CACHE or
  // $XDG_CACHE_HOME/lagoon (~/.cache/lagoon).
  std::filesystem::path pipeline_cache_dir;
  uint32_t frames_in_flight = 2;

  static ContextOptions from_environment();
};

struct DeviceInfo {
  std::string name;
  std::string type;            // "discrete GPU", "CPU", ...
  std::string driver_name;     // VkPhysicalDeviceDriverProperties: "llvmpipe", "NVIDIA", ...
  std::string driver_info;     // its driverInfo: "Mesa 22.3.6 (LLVM 15.0.6)", "550.54.14", ...
  std::string driver_version;  // VkPhysicalDeviceProperties::driverVersion decoded the vendor's way
  uint32_t api_version = 0;
  uint32_t index = 0;  // in vkEnumeratePhysicalDevices order, as LAGOON_DEVICE counts
};

class Context {
 public:
  static Result<std::unique_ptr<Context>> create(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  VkSurfaceKHR surface() const { return surface_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_properties_; }
  const DeviceInfo& device_info() const { return info_; }
  VkPipelineCache pipeline_cache() const { return pipeline_cache_; }
  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }
  ValidationLog& validation() { return *validation_log_; }
  DeferredDestroyer& deferred() { return deferred_; }

  // Memory type with all `required` flags (and `preferred` ones when possible); throws if none.
  uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred = 0) const;

  // Records with `record`, submits, waits. For set-up, uploads, readback and tests; not for the frame loop.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);
  void wait_idle() const;

  // Debug name shown in validation messages (no-op without the debug-utils extension).
  void set_name(VkObjectType type, uint64_t handle, const char* name) const;
  template <typename T>
  void set_name(T handle, VkObjectType type, const char* name) const {
    set_name(type, reinterpret_cast<uint64_t>(handle), name);
  }

  // Writes the pipeline cache now (it is also written on destruction).
  Result<void> save_pipeline_cache() const;
  const std::filesystem::path& pipeline_cache_file() const { return pipeline_cache_file_; }

 private:
  Context() = default;
  Result<void> init(const ContextOptions& options);
  Result<void> create_instance(const ContextOptions& options);
  Result<void> pick_device(const ContextOptions& options);
  void create_device();

  std::unique_ptr<ValidationLog> validation_log_ = std::make_unique<ValidationLog>();
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  DeviceInfo info_;
  bool debug_utils_ = false;
  PFN_vkSetDebugUtilsObjectNameEXT set_name_fn_ = nullptr;
  std::filesystem::path pipeline_cache_file_;
  // Destroyed before the device (members are destroyed in reverse order, and ~Context destroys the device).
  Unique<VkPipelineCache> pipeline_cache_;
  Unique<VkCommandPool> one_shot_pool_;
  Unique<VkFence> one_shot_fence_;
  DeferredDestroyer deferred_;
};

}  // namespace lagoon::vk
