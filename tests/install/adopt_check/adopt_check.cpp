// Checks Context::adopt() from a host's point of view, with the validation layer when LAGOON_VALIDATION=1:
// refusals name what is missing, and a context made by adopt() leaves the host's instance and device alive
// and destroys everything of its own (the layer reports objects still alive at vkDestroyDevice and
// vkDestroyInstance). Exit 0 when every check holds, 1 otherwise.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "vk/context.h"

namespace {

int failures = 0;

void expect(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    std::fprintf(stderr, "validation error: %s\n", data->pMessage);
    ++failures;
  }
  return VK_FALSE;
}

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// A device on `physical` with the given extensions and feature chain; queue family `family`, one queue.
struct HostDevice {
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::vector<const char*> extensions;  // `info` points into it
  VkDeviceCreateInfo info{};
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};

  HostDevice(VkPhysicalDevice physical, uint32_t family, std::vector<const char*> enabled,
             const void* features)
      : extensions(std::move(enabled)) {
    queue_info = {.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                  .queueFamilyIndex = family,
                  .queueCount = 1,
                  .pQueuePriorities = &priority};
    info = {.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
            .pNext = features,
            .queueCreateInfoCount = 1,
            .pQueueCreateInfos = &queue_info,
            .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
            .ppEnabledExtensionNames = extensions.data()};
    if (vkCreateDevice(physical, &info, nullptr, &device) != VK_SUCCESS) {
      std::fprintf(stderr, "adopt_check: vkCreateDevice failed\n");
      std::exit(1);
    }
    vkGetDeviceQueue(device, family, 0, &queue);
  }
  HostDevice(const HostDevice&) = delete;
  HostDevice& operator=(const HostDevice&) = delete;
  ~HostDevice() { vkDestroyDevice(device, nullptr); }
};

}  // namespace

int main() {
  const char* validation_env = std::getenv("LAGOON_VALIDATION");
  const bool validation = validation_env && std::string(validation_env) != "0";
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* debug_utils = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO, .apiVersion = VK_API_VERSION_1_3};
  const VkDebugUtilsMessengerCreateInfoEXT messenger_info{
      .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
      .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
      .messageType =
          VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
      .pfnUserCallback = &on_message};
  const VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                           .pNext = validation ? &messenger_info : nullptr,
                                           .pApplicationInfo = &app,
                                           .enabledLayerCount = validation ? 1u : 0u,
                                           .ppEnabledLayerNames = &layer,
                                           .enabledExtensionCount = validation ? 1u : 0u,
                                           .ppEnabledExtensionNames = &debug_utils};
  VkInstance instance;
  if (vkCreateInstance(&instance_info, nullptr, &instance) != VK_SUCCESS) {
    std::fprintf(stderr, "adopt_check: no Vulkan 1.3 instance\n");
    return 1;
  }
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    create(instance, &messenger_info, nullptr, &messenger);
  }

  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  const char* wanted_env = std::getenv("LAGOON_DEVICE");
  const std::string wanted = lowercase(wanted_env ? wanted_env : "");
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(d, &props);
    if (props.apiVersion >= VK_API_VERSION_1_3 &&
        lowercase(props.deviceName).find(wanted) != std::string::npos) {
      physical = d;
      break;
    }
  }
  if (physical == VK_NULL_HANDLE) {
    std::fprintf(stderr, "adopt_check: no Vulkan 1.3 device named like '%s'\n", wanted.c_str());
    return 1;
  }
  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &family_count, families.data());
  uint32_t family = 0;
  while (family < family_count &&
         (families[family].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) !=
             (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
    ++family;

  auto host_of = [&](const HostDevice& d) {
    return lagoon::vk::HostDevice{.instance = instance,
                                  .instance_api_version = VK_API_VERSION_1_3,
                                  .debug_utils = validation,
                                  .physical_device = physical,
                                  .device = d.device,
                                  .device_create_info = &d.info,
                                  .queue = d.queue,
                                  .queue_family = family};
  };

  {  // A plain device: no extension, no feature. Every missing piece is named at once.
    const HostDevice plain(physical, family, {}, nullptr);
    auto r = lagoon::vk::Context::adopt(host_of(plain));
    const std::string message = r ? "" : r.error().message;
    std::printf("      refusal: %s\n", message.c_str());
    expect(!r, "adopt() refuses a device made without Lagoon's extensions and features");
    for (const char* name : {"VK_KHR_push_descriptor", "dynamicRendering", "synchronization2"})
      expect(message.find(name) != std::string::npos, std::string("the refusal names ") + name);

    lagoon::vk::HostDevice no_info = host_of(plain);
    no_info.device_create_info = nullptr;
    auto r2 = lagoon::vk::Context::adopt(no_info);
    expect(!r2 && r2.error().message.find("device_create_info") != std::string::npos,
           "adopt() without device_create_info says it needs it");

    lagoon::vk::HostDevice old_instance = host_of(plain);
    old_instance.instance_api_version = VK_API_VERSION_1_2;
    auto r3 = lagoon::vk::Context::adopt(old_instance);
    expect(!r3 && r3.error().message.find("1.2") != std::string::npos,
           "adopt() refuses an instance created for Vulkan 1.2");
  }

  {  // A device made the way docs/embedding.md says: adopted, used, released; the host's device lives on.
    const lagoon::vk::RequiredFeatures features(physical);
    const HostDevice good(physical, family, lagoon::vk::required_device_extensions(), features.chain());
    {
      auto r = lagoon::vk::Context::adopt(host_of(good),
                                          {.frames_in_flight = 2, .validation_messenger = validation});
      if (!r) std::printf("      %s\n", r.error().message.c_str());
      expect(r.ok(), "adopt() accepts a device made with required_device_extensions() and RequiredFeatures");
      if (r) {
        lagoon::vk::Context& ctx = **r;
        expect(ctx.adopted() && ctx.device() == good.device && ctx.queue() == good.queue &&
                   ctx.instance() == instance,
               "the context uses the host's instance, device and queue");
        expect(ctx.validation_enabled() == validation, "validation_messenger adds Lagoon's messenger");
        expect(ctx.enabled_features().shaderFloat64 == features.features2.features.shaderFloat64,
               "enabled_features() are the host's");
        expect(ctx.deferred().slots() == 2, "frames_in_flight sets the deferred-destruction slots");
        bool ran = false;
        ctx.submit_and_wait([&](VkCommandBuffer) { ran = true; });
        expect(ran, "submit_and_wait() runs on the host's queue");
      }
    }
    // The context is gone: the host's device must still work.
    VkFence fence = VK_NULL_HANDLE;
    const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    expect(vkCreateFence(good.device, &fence_info, nullptr, &fence) == VK_SUCCESS &&
               vkQueueWaitIdle(good.queue) == VK_SUCCESS,
           "the host's device still works after the context is destroyed");
    vkDestroyFence(good.device, fence, nullptr);
  }  // vkDestroyDevice: the layer reports anything of Lagoon's still alive

  if (messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance, messenger, nullptr);
  }
  vkDestroyInstance(instance, nullptr);
  if (failures) std::fprintf(stderr, "adopt_check: %d failure(s)\n", failures);
  return failures ? 1 : 0;
}
