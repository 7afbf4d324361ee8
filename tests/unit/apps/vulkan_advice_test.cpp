// The advice the executables add to a Vulkan error that ends a command (apps/common/vulkan_advice.h).
#include "vulkan_advice.h"

#include <gtest/gtest.h>

namespace lagoon::test {
namespace {

TEST(VulkanAdvice, DeviceLostSaysNothingWasWrittenAndHowToReport) {
  const std::string text = cli::explain_vulkan_error(
      vk::VulkanError("vkQueueSubmit2 failed with VK_ERROR_DEVICE_LOST", VK_ERROR_DEVICE_LOST));
  EXPECT_EQ(text.rfind("vkQueueSubmit2 failed with VK_ERROR_DEVICE_LOST.\n", 0), 0u) << text;
  EXPECT_NE(text.find("Nothing was written"), std::string::npos) << text;
  EXPECT_NE(text.find("lagoon info"), std::string::npos) << text;
}

TEST(VulkanAdvice, OutOfMemoryNamesWhatToLower) {
  for (VkResult r : {VK_ERROR_OUT_OF_DEVICE_MEMORY, VK_ERROR_OUT_OF_HOST_MEMORY}) {
    const std::string text = cli::explain_vulkan_error(vk::VulkanError("out of memory", r));
    EXPECT_NE(text.find("render.width"), std::string::npos) << text;
    EXPECT_NE(text.find("ocean.cascades"), std::string::npos) << text;
  }
}

TEST(VulkanAdvice, OtherErrorsAreLeftAsTheyAre) {
  EXPECT_EQ(cli::explain_vulkan_error(vk::VulkanError("x failed", VK_ERROR_INITIALIZATION_FAILED)),
            "x failed");
}

}  // namespace
}  // namespace lagoon::test
