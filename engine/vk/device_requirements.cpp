#include "vk/device_requirements.h"

#include <cstring>

#include "vk/check.h"
#include "vk/device_select.h"

namespace lagoon::vk {
namespace {

bool has_device_extension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> exts(count);
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data()));
  for (const auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

// Both the instance and the device must be 1.3: Lagoon calls 1.3 commands (vkCmdPipelineBarrier2,
// vkQueueSubmit2, dynamic rendering) as core commands.
void check_api_versions(const HostDevice& host, const VkPhysicalDeviceProperties& props,
                        std::vector<std::string>& missing) {
  if (host.instance_api_version < kRequiredApiVersion)
    missing.push_back("the instance was created for Vulkan " + api_version_string(host.instance_api_version) +
                      " (HostDevice::instance_api_version), not 1.3 or later");
  if (props.apiVersion < kRequiredApiVersion)
    missing.push_back("the device has Vulkan " + api_version_string(props.apiVersion) + ", not 1.3 or later");
}

// The ocean step (compute) and the passes (graphics) are recorded into one command buffer.
void check_queue_family(const HostDevice& host, std::vector<std::string>& missing) {
  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(host.physical_device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(host.physical_device, &family_count, families.data());
  const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if (host.queue_family >= family_count || (families[host.queue_family].queueFlags & need) != need)
    missing.push_back("queue family " + std::to_string(host.queue_family) +
                      " (HostDevice::queue_family) does not do both graphics and compute");
}

void check_extensions(const HostDevice& host, std::vector<std::string>& missing) {
  const VkDeviceCreateInfo& info = *host.device_create_info;
  for (const char* name : required_device_extensions()) {
    bool enabled = false;
    for (uint32_t i = 0; i < info.enabledExtensionCount; ++i)
      enabled = enabled || std::strcmp(info.ppEnabledExtensionNames[i], name) == 0;
    if (!enabled)
      missing.push_back(std::string("device extension ") + name +
                        (has_device_extension(host.physical_device, name)
                             ? " is not enabled"
                             : " is not supported by the device"));
  }
}

struct Vulkan13Needs {
  bool dynamic_rendering = false, synchronization2 = false;
};

// What the host enabled of the 1.3 features Lagoon needs: either in VkPhysicalDeviceVulkan13Features or in
// their own (promoted extension) structs in the chain.
Vulkan13Needs enabled_vulkan13(const VkDeviceCreateInfo& info) {
  Vulkan13Needs enabled;
  for (auto* s = static_cast<const VkBaseInStructure*>(info.pNext); s != nullptr; s = s->pNext) {
    switch (s->sType) {
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES: {
        auto* f = reinterpret_cast<const VkPhysicalDeviceVulkan13Features*>(s);
        enabled.dynamic_rendering = enabled.dynamic_rendering || f->dynamicRendering;
        enabled.synchronization2 = enabled.synchronization2 || f->synchronization2;
        break;
      }
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES:
        enabled.dynamic_rendering =
            enabled.dynamic_rendering ||
            reinterpret_cast<const VkPhysicalDeviceDynamicRenderingFeatures*>(s)->dynamicRendering;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES:
        enabled.synchronization2 =
            enabled.synchronization2 ||
            reinterpret_cast<const VkPhysicalDeviceSynchronization2Features*>(s)->synchronization2;
        break;
      default:
        break;
    }
  }
  return enabled;
}

// What the device supports of them. vkGetPhysicalDeviceFeatures2 needs a 1.1 instance; the 1.3 struct a 1.3
// device. Otherwise nothing counts as supported (the version is reported as missing already).
Vulkan13Needs supported_vulkan13(const HostDevice& host, const VkPhysicalDeviceProperties& props) {
  VkPhysicalDeviceVulkan13Features f13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  if (host.instance_api_version >= VK_API_VERSION_1_1 && props.apiVersion >= kRequiredApiVersion) {
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f13};
    vkGetPhysicalDeviceFeatures2(host.physical_device, &features);
  }
  return {.dynamic_rendering = f13.dynamicRendering != VK_FALSE,
          .synchronization2 = f13.synchronization2 != VK_FALSE};
}

void check_feature(const char* name, bool enabled, bool supported, std::vector<std::string>& missing) {
  if (!enabled)
    missing.push_back(std::string("feature ") + name +
                      (supported ? " is not enabled" : " is not supported by the device"));
}

}  // namespace

namespace detail {

int find_queue_family(VkPhysicalDevice device, VkSurfaceKHR surface) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[i].queueFlags & need) != need) continue;
    if (surface != VK_NULL_HANDLE) {
      VkBool32 present = VK_FALSE;
      VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present));
      if (!present) continue;
    }
    return static_cast<int>(i);
  }
  return -1;
}

std::string unsuitable_reason(VkPhysicalDevice device, VkSurfaceKHR surface) {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(device, &props);
  if (props.apiVersion < VK_API_VERSION_1_3) return "Vulkan 1.3 is required";
  VkPhysicalDeviceVulkan13Features f13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f13};
  vkGetPhysicalDeviceFeatures2(device, &features);
  if (!f13.dynamicRendering) return "dynamicRendering is not supported";
  if (!f13.synchronization2) return "synchronization2 is not supported";
  if (!has_device_extension(device, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
    return VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME " is not supported";
  if (surface != VK_NULL_HANDLE && !has_device_extension(device, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
    return "no swapchain support";
  if (find_queue_family(device, surface) < 0)
    return surface ? "no queue does graphics, compute and present" : "no queue does graphics and compute";
  return "";
}

std::vector<std::string> host_device_shortfalls(const HostDevice& host) {
  std::vector<std::string> missing;
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(host.physical_device, &props);
  check_api_versions(host, props, missing);
  check_queue_family(host, missing);
  check_extensions(host, missing);
  const Vulkan13Needs enabled = enabled_vulkan13(*host.device_create_info);
  const Vulkan13Needs supported = supported_vulkan13(host, props);
  check_feature("dynamicRendering", enabled.dynamic_rendering, supported.dynamic_rendering, missing);
  check_feature("synchronization2", enabled.synchronization2, supported.synchronization2, missing);
  return missing;
}

VkPhysicalDeviceFeatures enabled_core_features(const VkDeviceCreateInfo& info) {
  const VkPhysicalDeviceFeatures* core = info.pEnabledFeatures;
  for (auto* s = static_cast<const VkBaseInStructure*>(info.pNext); s != nullptr; s = s->pNext)
    if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2)
      core = &reinterpret_cast<const VkPhysicalDeviceFeatures2*>(s)->features;
  return core ? *core : VkPhysicalDeviceFeatures{};
}

}  // namespace detail

std::vector<const char*> required_device_extensions() {
  return {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
}

RequiredFeatures::RequiredFeatures(VkPhysicalDevice optional_from) {
  features2.pNext = &vulkan11;
  vulkan11.pNext = &vulkan12;
  vulkan12.pNext = &vulkan13;
  vulkan13.synchronization2 = VK_TRUE;
  vulkan13.dynamicRendering = VK_TRUE;
  if (optional_from == VK_NULL_HANDLE) return;
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(optional_from, &supported);
  // Optional features used when present (64-bit floats in tests). Not samplerAnisotropy: Lagoon filters
  // isotropically on every device, as anisotropic filters differ between vendors (docs/devices.md).
  features2.features.shaderFloat64 = supported.shaderFloat64;
  features2.features.fillModeNonSolid = supported.fillModeNonSolid;
}

}  // namespace lagoon::vk
