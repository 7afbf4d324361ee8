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

}  // namespace
}  // namespace lagoon::vk
