#include "vk/device_select.h"

#include <gtest/gtest.h>

namespace lagoon::vk {
namespace {

const DeviceCandidate kCpu{"llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU, ""};
const DeviceCandidate kIntegrated{"Intel(R) UHD Graphics 620", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, ""};
const DeviceCandidate kDiscrete{"NVIDIA GeForce RTX 3060", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, ""};
const DeviceCandidate kVirtual{"virtio-gpu", VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU, ""};

TEST(DeviceSelect, PrefersDiscreteThenIntegratedThenVirtualThenCpu) {
  EXPECT_EQ(*choose_device({kCpu, kIntegrated, kDiscrete, kVirtual}, ""), 2u);
  EXPECT_EQ(*choose_device({kCpu, kVirtual, kIntegrated}, ""), 2u);
  EXPECT_EQ(*choose_device({kCpu, kVirtual}, ""), 1u);
  EXPECT_EQ(*choose_device({kCpu}, ""), 0u);
}

TEST(DeviceSelect, SkipsUnsuitableDevices) {
  DeviceCandidate old = kDiscrete;
  old.unsuitable_reason = "Vulkan 1.3 is required";
  EXPECT_EQ(*choose_device({old, kCpu}, ""), 1u);
  auto none = choose_device({old}, "");
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("Vulkan 1.3 is required"), std::string::npos);
}

TEST(DeviceSelect, OverrideByIndexOrCaseInsensitiveName) {
  EXPECT_EQ(*choose_device({kDiscrete, kCpu}, "1"), 1u);
  EXPECT_EQ(*choose_device({kDiscrete, kCpu}, "LLVMPIPE"), 1u);
  EXPECT_EQ(*choose_device({kCpu, kDiscrete}, "rtx"), 1u);
}

TEST(DeviceSelect, BadOverridesListTheDevices) {
  auto out_of_range = choose_device({kCpu}, "3");
  ASSERT_FALSE(out_of_range);
  EXPECT_NE(out_of_range.error().message.find("out of range"), std::string::npos);
  EXPECT_NE(out_of_range.error().message.find("0: llvmpipe"), std::string::npos);
  auto no_match = choose_device({kCpu}, "radeon");
  ASSERT_FALSE(no_match);
  EXPECT_NE(no_match.error().message.find("matches no device"), std::string::npos);
  DeviceCandidate old = kDiscrete;
  old.unsuitable_reason = "dynamicRendering is not supported";
  auto unsuitable = choose_device({old, kCpu}, "nvidia");
  ASSERT_FALSE(unsuitable);
  EXPECT_NE(unsuitable.error().message.find("dynamicRendering"), std::string::npos);
}

TEST(DeviceSelect, NoDeviceNamesThePackage) {
  auto none = choose_device({}, "");
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().message.find("mesa-vulkan-drivers"), std::string::npos);
}

TEST(DeviceSelect, VersionsAreDecodedTheVendorsWay) {
  EXPECT_EQ(api_version_string(VK_MAKE_API_VERSION(0, 1, 3, 255)), "1.3.255");
  EXPECT_EQ(driver_version_string(VK_DRIVER_ID_NVIDIA_PROPRIETARY, (550u << 22) | (54u << 14) | (14u << 6)),
            "550.54.14");
  EXPECT_EQ(
      driver_version_string(VK_DRIVER_ID_NVIDIA_PROPRIETARY, (535u << 22) | (1u << 14) | (2u << 6) | 3u),
      "535.1.2.3");
  EXPECT_EQ(driver_version_string(VK_DRIVER_ID_INTEL_PROPRIETARY_WINDOWS, (101u << 14) | 5333u), "101.5333");
  EXPECT_EQ(driver_version_string(VK_DRIVER_ID_MESA_LLVMPIPE, VK_MAKE_VERSION(22, 3, 6)), "22.3.6");
}

}  // namespace
}  // namespace lagoon::vk
