#include "vulkan_advice.h"

namespace lagoon::cli {

std::string explain_vulkan_error(const vk::VulkanError& error) {
  std::string text = error.what();
  switch (error.result()) {
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
    case VK_ERROR_OUT_OF_HOST_MEMORY:
      text +=
          ".\nThe scene needs more memory than the device has. Lower render.width/render.height (--width, "
          "--height), use fewer or smaller ocean.cascades (resolution 256 instead of 1024), or choose a "
          "device "
          "with more memory (LAGOON_DEVICE; `lagoon info` lists them).";
      break;
    case VK_ERROR_DEVICE_LOST:
      text +=
          ".\nThe GPU stopped responding (a driver reset, a hang, or the device was removed). Nothing was "
          "written. Run the command again; if it repeats, check the driver's log (dmesg) and report it with "
          "the output of `lagoon info`.";
      break;
    default:
      break;
  }
  return text;
}

}  // namespace lagoon::cli
