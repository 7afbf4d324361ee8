// Which physical device to use: a pure function of what the driver reports, so it is unit-tested without
// Vulkan. Preference discrete > integrated > virtual > CPU; LAGOON_DEVICE=<index or name substring>
// overrides.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"

namespace lagoon::vk {

struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::string unsuitable_reason;  // empty when the device has everything Lagoon needs
};

const char* device_type_name(VkPhysicalDeviceType type);

// "1.3.255" for a VK_MAKE_API_VERSION value (VkPhysicalDeviceProperties::apiVersion).
std::string api_version_string(uint32_t version);

// VkPhysicalDeviceProperties::driverVersion as the vendor writes it. Its layout is the driver's choice:
// NVIDIA packs 10.8.8.6 bits ("550.54.14"), Intel's Windows driver 18.14 bits ("101.5333"), Mesa and most
// others use the Vulkan version layout ("23.2.1").
std::string driver_version_string(VkDriverId driver, uint32_t version);

// Returns the index of the device to use. `override_spec` is LAGOON_DEVICE's value ("" = automatic).
Result<size_t> choose_device(const std::vector<DeviceCandidate>& devices, std::string_view override_spec);

}  // namespace lagoon::vk
