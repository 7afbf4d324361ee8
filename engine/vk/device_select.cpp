#include "vk/device_select.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace lagoon::vk {
namespace {

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

std::string describe(const std::vector<DeviceCandidate>& devices) {
  std::string out;
  for (size_t i = 0; i < devices.size(); ++i) {
    out +=
        "\n  " + std::to_string(i) + ": " + devices[i].name + " (" + device_type_name(devices[i].type) + ")";
    if (!devices[i].unsuitable_reason.empty()) out += " - unsuitable: " + devices[i].unsuitable_reason;
  }
  return out;
}

}  // namespace

const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other";
  }
}

std::string api_version_string(uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) +
         "." + std::to_string(VK_API_VERSION_PATCH(version));
}

std::string driver_version_string(VkDriverId driver, uint32_t version) {
  if (driver == VK_DRIVER_ID_NVIDIA_PROPRIETARY) {
    std::string text = std::to_string(version >> 22) + "." + std::to_string((version >> 14) & 0xff) + "." +
                       std::to_string((version >> 6) & 0xff);
    if (const uint32_t fourth = version & 0x3f; fourth != 0) text += "." + std::to_string(fourth);
    return text;
  }
  if (driver == VK_DRIVER_ID_INTEL_PROPRIETARY_WINDOWS)
    return std::to_string(version >> 14) + "." + std::to_string(version & 0x3fff);
  // VK_VERSION_* rather than VK_API_VERSION_*: drivers fill the top bits too, which API_VERSION reads as
  // a variant and drops.
  return std::to_string(version >> 22) + "." + std::to_string((version >> 12) & 0x3ff) + "." +
         std::to_string(version & 0xfff);
}

Result<size_t> choose_device(const std::vector<DeviceCandidate>& devices, std::string_view override_spec) {
  if (devices.empty()) {
    return make_error(
        "no Vulkan device found. Install a driver: 'sudo apt-get install mesa-vulkan-drivers' gives "
        "lavapipe, "
        "a CPU Vulkan device that needs no GPU (or run tools/install-deps.sh). If VK_ICD_FILENAMES is set, "
        "check that it names an existing ICD file.");
  }
  if (!override_spec.empty()) {
    std::vector<size_t> matches;
    size_t index = 0;
    auto [end, ec] =
        std::from_chars(override_spec.data(), override_spec.data() + override_spec.size(), index);
    if (ec == std::errc() && end == override_spec.data() + override_spec.size()) {
      if (index >= devices.size())
        return make_error("LAGOON_DEVICE=" + std::string(override_spec) +
                          " is out of range; devices are:" + describe(devices));
      matches.push_back(index);
    } else {
      const std::string needle = lower(override_spec);
      for (size_t i = 0; i < devices.size(); ++i)
        if (lower(devices[i].name).find(needle) != std::string::npos) matches.push_back(i);
      if (matches.empty())
        return make_error(
            "LAGOON_DEVICE=" + std::string(override_spec) +
            " matches no device name; use an index or part of a name from:" + describe(devices));
    }
    // Of several name matches take the first suitable one; report why when none is.
    for (size_t i : matches)
      if (devices[i].unsuitable_reason.empty()) return i;
    return make_error("LAGOON_DEVICE=" + std::string(override_spec) + " selects " + devices[matches[0]].name +
                      ", which cannot run Lagoon: " + devices[matches[0]].unsuitable_reason);
  }
  size_t best = devices.size();
  for (size_t i = 0; i < devices.size(); ++i) {
    if (!devices[i].unsuitable_reason.empty()) continue;
    if (best == devices.size() || type_rank(devices[i].type) > type_rank(devices[best].type)) best = i;
  }
  if (best == devices.size())
    return make_error(
        "no Vulkan device can run Lagoon (it needs Vulkan 1.3 with dynamic rendering, "
        "synchronization2 and VK_KHR_push_descriptor):" +
        describe(devices) + "\nUpdate the driver, or install mesa-vulkan-drivers for lavapipe.");
  return best;
}

}  // namespace lagoon::vk
