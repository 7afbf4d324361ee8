#include "vk/context.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "core/cache_dir.h"
#include "vk/check.h"
#include "vk/device_requirements.h"
#include "vk/device_select.h"
#include "vk/pipeline_cache.h"

namespace lagoon::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

bool has_layer(const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool has_instance_extension(const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> exts(count);
  VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, exts.data()));
  for (const auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

VkDebugUtilsMessengerCreateInfoEXT messenger_create_info(ValidationLog* log) {
  return {.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
          .messageSeverity =
              VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
          .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
          .pfnUserCallback = &ValidationLog::callback,
          .pUserData = log};
}

}  // namespace

AdoptOptions AdoptOptions::from_environment() {
  return {.pipeline_cache_dir = cache_dir_from_environment()};
}

ContextOptions ContextOptions::from_environment() {
  ContextOptions options;
  const std::string v = env("LAGOON_VALIDATION");
  options.validation = !v.empty() && v != "0";
  options.device_override = env("LAGOON_DEVICE");
  options.pipeline_cache_dir = cache_dir_from_environment();
  return options;
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
  std::unique_ptr<Context> ctx(new Context());
  ctx->deferred_ = DeferredDestroyer(options.frames_in_flight);
  if (auto r = ctx->init(options); !r) return r.error();
  return ctx;
}

Result<void> Context::init(const ContextOptions& options) {
  if (auto r = create_instance(options); !r) return r;
  if (options.create_surface) {
    surface_ = options.create_surface(instance_);
    if (surface_ == VK_NULL_HANDLE) return make_error("could not create a Vulkan surface for the window");
  }
  if (auto r = pick_device(options); !r) return r;
  create_device();
  create_own_objects(options.pipeline_cache_dir);
  return {};
}

Result<std::unique_ptr<Context>> Context::adopt(const HostDevice& host, const AdoptOptions& options) {
  if (host.instance == VK_NULL_HANDLE || host.physical_device == VK_NULL_HANDLE ||
      host.device == VK_NULL_HANDLE || host.queue == VK_NULL_HANDLE)
    return make_error(
        "Context::adopt: HostDevice needs the host's instance, physical_device, device and queue "
        "(one of them is VK_NULL_HANDLE)");
  if (host.device_create_info == nullptr)
    return make_error(
        "Context::adopt: HostDevice::device_create_info is null; pass the VkDeviceCreateInfo the device was "
        "created with (Vulkan cannot be asked which extensions and features a device has enabled)");
  if (options.frames_in_flight == 0)
    return make_error("Context::adopt: AdoptOptions::frames_in_flight must be >= 1");
  if (auto missing = detail::host_device_shortfalls(host); !missing.empty()) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(host.physical_device, &props);
    std::string message =
        std::string("Context::adopt: Lagoon cannot use the host's device \"") + props.deviceName + "\": ";
    for (size_t i = 0; i < missing.size(); ++i) message += (i ? "; " : "") + missing[i];
    message +=
        ". Create it with vk::required_device_extensions() and the chain of vk::RequiredFeatures "
        "(docs/embedding.md)";
    return make_error(message);
  }

  std::unique_ptr<Context> ctx(new Context());
  ctx->adopted_ = true;
  ctx->deferred_ = DeferredDestroyer(options.frames_in_flight);
  ctx->instance_ = host.instance;
  ctx->physical_device_ = host.physical_device;
  ctx->device_ = host.device;
  ctx->queue_ = host.queue;
  ctx->queue_family_ = host.queue_family;
  ctx->enabled_features_ = detail::enabled_core_features(*host.device_create_info);
  ctx->debug_utils_ = host.debug_utils;
  if (ctx->debug_utils_)
    ctx->set_name_fn_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(host.instance, "vkSetDebugUtilsObjectNameEXT"));

  // DeviceInfo::index counts as LAGOON_DEVICE does, in the host instance's enumeration order.
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(host.instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(host.instance, &count, devices.data()));
  uint32_t index = 0;
  for (uint32_t i = 0; i < count; ++i)
    if (devices[i] == host.physical_device) index = i;
  ctx->read_device_info(index);

  if (options.validation_messenger) {
    if (!host.debug_utils)
      return make_error(
          "Context::adopt: AdoptOptions::validation_messenger needs VK_EXT_debug_utils enabled on the host's "
          "instance (and HostDevice::debug_utils = true)");
    if (auto r = ctx->install_messenger(); !r) return r.error();
  }
  ctx->create_own_objects(options.pipeline_cache_dir);
  return ctx;
}

Result<void> Context::install_messenger() {
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  if (create == nullptr) return make_error("Context::adopt: vkCreateDebugUtilsMessengerEXT is not available");
  const VkDebugUtilsMessengerCreateInfoEXT info = messenger_create_info(validation_log_.get());
  VK_CHECK(create(instance_, &info, nullptr, &messenger_));
  return {};
}

Result<void> Context::create_instance(const ContextOptions& options) {
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  for (const auto& e : options.instance_extensions) extensions.push_back(e.c_str());
  if (options.validation) {
    if (!has_layer(kValidationLayer))
      return make_error(
          "LAGOON_VALIDATION is on but the Vulkan validation layer is not installed: "
          "'sudo apt-get install vulkan-validationlayers' (or run tools/install-deps.sh)");
    layers.push_back(kValidationLayer);
  }
  debug_utils_ = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME) && options.validation;
  if (debug_utils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "lagoon",
                              .applicationVersion = VK_MAKE_VERSION(0, 1, 0),
                              .pEngineName = "lagoon",
                              .engineVersion = VK_MAKE_VERSION(0, 1, 0),
                              .apiVersion = VK_API_VERSION_1_3};
  const VkDebugUtilsMessengerCreateInfoEXT messenger_info = messenger_create_info(validation_log_.get());
  // Synchronization validation catches missing barriers, which core validation does not.
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  const VkValidationFeaturesEXT features{.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
                                         .pNext = debug_utils_ ? &messenger_info : nullptr,
                                         .enabledValidationFeatureCount = 1,
                                         .pEnabledValidationFeatures = enables};
  const VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                  .pNext = options.validation ? static_cast<const void*>(&features) : nullptr,
                                  .pApplicationInfo = &app,
                                  .enabledLayerCount = static_cast<uint32_t>(layers.size()),
                                  .ppEnabledLayerNames = layers.data(),
                                  .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                                  .ppEnabledExtensionNames = extensions.data()};
  const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER) return choose_device({}, "").error();
  if (r == VK_ERROR_EXTENSION_NOT_PRESENT)
    return make_error(
        "the Vulkan loader lacks an instance extension the window needs (a display driver for "
        "surfaces); run headless or install the platform's Vulkan WSI support");
  if (r != VK_SUCCESS) return make_error(std::string("vkCreateInstance failed: ") + result_string(r));
  if (debug_utils_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    VK_CHECK(create(instance_, &messenger_info, nullptr, &messenger_));
    set_name_fn_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
  }
  return {};
}

Result<void> Context::pick_device(const ContextOptions& options) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
  std::vector<DeviceCandidate> candidates;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(d, &props);
    candidates.push_back({.name = props.deviceName,
                          .type = props.deviceType,
                          .unsuitable_reason = detail::unsuitable_reason(d, surface_)});
  }
  auto chosen = choose_device(candidates, options.device_override);
  if (!chosen) return chosen.error();
  candidates_ = std::move(candidates);
  physical_device_ = devices[*chosen];
  queue_family_ = static_cast<uint32_t>(detail::find_queue_family(physical_device_, surface_));
  read_device_info(static_cast<uint32_t>(*chosen));
  return {};
}

void Context::read_device_info(uint32_t index) {
  VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                     .pNext = &driver};
  vkGetPhysicalDeviceProperties2(physical_device_, &props2);
  properties_ = props2.properties;
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
  info_ = {.name = properties_.deviceName,
           .type = device_type_name(properties_.deviceType),
           .driver_name = driver.driverName,
           .driver_info = driver.driverInfo,
           .driver_version = driver_version_string(driver.driverID, properties_.driverVersion),
           .api_version = properties_.apiVersion,
           .index = index};
}

void Context::create_device() {
  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                           .queueFamilyIndex = queue_family_,
                                           .queueCount = 1,
                                           .pQueuePriorities = &priority};
  std::vector<const char*> extensions = required_device_extensions();
  if (surface_ != VK_NULL_HANDLE) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  // The same chain a host gets for adopt(), so the two paths cannot drift apart.
  const RequiredFeatures features(physical_device_);
  enabled_features_ = features.features2.features;

  const VkDeviceCreateInfo info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                .pNext = features.chain(),
                                .queueCreateInfoCount = 1,
                                .pQueueCreateInfos = &queue_info,
                                .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                                .ppEnabledExtensionNames = extensions.data()};
  VK_CHECK(vkCreateDevice(physical_device_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
}

// What a context owns on either path: the one-shot pool and fence and the pipeline cache.
void Context::create_own_objects(const std::filesystem::path& pipeline_cache_dir) {
  const VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                          .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                          .queueFamilyIndex = queue_family_};
  VkCommandPool pool;
  VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &pool));
  one_shot_pool_ = Unique<VkCommandPool>(device_, pool);
  const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence;
  VK_CHECK(vkCreateFence(device_, &fence_info, nullptr, &fence));
  one_shot_fence_ = Unique<VkFence>(device_, fence);
  if (!pipeline_cache_dir.empty())
    pipeline_cache_file_ = pipeline_cache_dir / pipeline_cache_file_name(properties_);
  pipeline_cache_ = load_pipeline_cache(device_, properties_, pipeline_cache_file_);
}

Context::~Context() {
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    deferred_.flush_all();
    if (auto r = save_pipeline_cache(); !r) std::fprintf(stderr, "lagoon: %s\n", r.error().message.c_str());
    pipeline_cache_.reset();
    one_shot_fence_.reset();
    one_shot_pool_.reset();
    // An adopted device (and its instance) belongs to the host, which destroys it after this context.
    if (!adopted_) vkDestroyDevice(device_, nullptr);
  }
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  // The messenger is ours on both paths (adopt() makes one only when asked to).
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE && !adopted_) vkDestroyInstance(instance_, nullptr);
}

uint32_t Context::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred) const {
  int fallback = -1;
  for (uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i) {
    if (!(type_bits & (1u << i))) continue;
    const VkMemoryPropertyFlags flags = memory_properties_.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  if (fallback < 0)
    throw_usage_error("no Vulkan memory type has the required properties 0x" + std::to_string(required));
  return static_cast<uint32_t>(fallback);
}

void Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                          .commandPool = one_shot_pool_,
                                          .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                          .commandBufferCount = 1};
  VkCommandBuffer cmd;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
  const VkCommandBufferSubmitInfo cmd_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                           .commandBuffer = cmd};
  const VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &cmd_info};
  VkFence fence = one_shot_fence_;
  VK_CHECK(vkResetFences(device_, 1, &fence));
  VK_CHECK(vkQueueSubmit2(queue_, 1, &submit, fence));
  VK_CHECK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));
  vkFreeCommandBuffers(device_, one_shot_pool_, 1, &cmd);
}

void Context::wait_idle() const {
  VK_CHECK(vkDeviceWaitIdle(device_));
}

void Context::set_name(VkObjectType type, uint64_t handle, const char* name) const {
  if (!debug_utils_ || name == nullptr) return;
  const auto fn = set_name_fn_;
  const VkDebugUtilsObjectNameInfoEXT info{.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT,
                                           .objectType = type,
                                           .objectHandle = handle,
                                           .pObjectName = name};
  if (fn) VK_CHECK(fn(device_, &info));
}

Result<void> Context::save_pipeline_cache() const {
  if (pipeline_cache_file_.empty() || !pipeline_cache_) return {};
  return vk::save_pipeline_cache(device_, pipeline_cache_, pipeline_cache_file_);
}

}  // namespace lagoon::vk
