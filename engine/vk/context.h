// The Vulkan context: instance, validation, the chosen device and its one graphics+compute queue,
// pipeline cache, deferred destruction and one-shot submission. Headless by default; give
// ContextOptions::create_surface (and the window's instance extensions) to also present to a window.
// Context::adopt() wraps a host engine's own instance and device instead (docs/embedding.md).
#pragma once
#include <vulkan/vulkan.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "vk/deferred.h"
#include "vk/device_select.h"
#include "vk/handle.h"
#include "vk/pipeline_registry.h"
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

// What Lagoon needs of a device: Vulkan 1.3, these device extensions, the features RequiredFeatures turns on
// and a queue family doing graphics and compute.
inline constexpr uint32_t kRequiredApiVersion = VK_API_VERSION_1_3;
std::vector<const char*> required_device_extensions();

// The feature chain to give vkCreateDevice (VkDeviceCreateInfo::pNext = chain()): the required features
// (dynamicRendering, synchronization2) and, when constructed with a device, the optional ones Lagoon uses
// where that device has them (shaderFloat64, fillModeNonSolid). A host that needs features of its own sets
// them in these structs (a chain may hold each struct type once) and may hang further structs on
// vulkan13.pNext. Not copyable: the structs point at each other.
struct RequiredFeatures {
  VkPhysicalDeviceFeatures2 features2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan11Features vulkan11{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan12Features vulkan12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features vulkan13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};

  explicit RequiredFeatures(VkPhysicalDevice optional_from = VK_NULL_HANDLE);
  RequiredFeatures(const RequiredFeatures&) = delete;
  RequiredFeatures& operator=(const RequiredFeatures&) = delete;
  const VkPhysicalDeviceFeatures2* chain() const { return &features2; }
};

// A host engine's Vulkan objects for Context::adopt(). The host keeps owning all of them: Lagoon never
// destroys them and must be destroyed before them. Lagoon submits its set-up work (uploads, warm-up,
// readback) to `queue` from the thread calling it, so the host must not use `queue` from another thread at
// the same time.
struct HostDevice {
  VkInstance instance = VK_NULL_HANDLE;
  // VkApplicationInfo::apiVersion the instance was created with: Lagoon calls Vulkan 1.3 commands.
  uint32_t instance_api_version = 0;
  // VK_EXT_debug_utils is enabled on the instance: Lagoon then names its objects for validation messages.
  bool debug_utils = false;
  VkPhysicalDevice physical_device = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  // Exactly what vkCreateDevice was given (its extensions and pNext feature chain are checked; Vulkan has no
  // query for what a device was created with). Read during adopt() only.
  const VkDeviceCreateInfo* device_create_info = nullptr;
  VkQueue queue = VK_NULL_HANDLE;  // a queue of `queue_family`
  uint32_t queue_family = 0;       // must do graphics and compute
};

struct AdoptOptions {
  // Frames the host may have in flight: objects Lagoon retires are destroyed `frames_in_flight` frames later
  // (the host calls deferred().begin_frame(slot) after waiting for that slot's previous frame).
  uint32_t frames_in_flight = 2;
  // As ContextOptions::pipeline_cache_dir; empty = no persistence.
  std::filesystem::path pipeline_cache_dir;
  // Adds a debug messenger (needs HostDevice::debug_utils) whose messages go to validation(); off when the
  // host reads the validation layer's messages itself.
  bool validation_messenger = false;

  // pipeline_cache_dir from LAGOON_PIPELINE_CACHE / XDG_CACHE_HOME, as ContextOptions::from_environment.
  static AdoptOptions from_environment();
};

class Context {
 public:
  static Result<std::unique_ptr<Context>> create(const ContextOptions& options);
  // Wraps a host's instance and device (docs/embedding.md). Fails, naming each missing piece, when the device
  // lacks Vulkan 1.3, an extension of required_device_extensions() or a feature of RequiredFeatures.
  static Result<std::unique_ptr<Context>> adopt(const HostDevice& host, const AdoptOptions& options = {});
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
  // Every device the instance offered (vkEnumeratePhysicalDevices order, as LAGOON_DEVICE counts) and why a
  // device was unusable; device_info().index is the one chosen. Empty for an adopted device.
  const std::vector<DeviceCandidate>& device_candidates() const { return candidates_; }
  VkPipelineCache pipeline_cache() const { return pipeline_cache_; }
  // The core features the device was created with (create(): as RequiredFeatures(physical_device());
  // adopt(): the host's).
  const VkPhysicalDeviceFeatures& enabled_features() const { return enabled_features_; }
  // True for a context made by adopt(): the instance and device belong to the host.
  bool adopted() const { return adopted_; }
  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }
  ValidationLog& validation() { return *validation_log_; }
  DeferredDestroyer& deferred() { return deferred_; }
  // The pipelines declared on this device, and those made (vk/pipeline_registry.h).
  PipelineRegistry& pipelines() const { return pipelines_; }

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
  void read_device_info(uint32_t index);
  void create_device();
  void create_own_objects(const std::filesystem::path& pipeline_cache_dir);
  Result<void> install_messenger();

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
  std::vector<DeviceCandidate> candidates_;
  VkPhysicalDeviceFeatures enabled_features_{};
  bool adopted_ = false;
  bool debug_utils_ = false;
  PFN_vkSetDebugUtilsObjectNameEXT set_name_fn_ = nullptr;
  std::filesystem::path pipeline_cache_file_;
  // Destroyed before the device (members are destroyed in reverse order, and ~Context destroys the device
  // unless adopted).
  Unique<VkPipelineCache> pipeline_cache_;
  Unique<VkCommandPool> one_shot_pool_;
  Unique<VkFence> one_shot_fence_;
  DeferredDestroyer deferred_;
  mutable PipelineRegistry pipelines_;
};

}  // namespace lagoon::vk
