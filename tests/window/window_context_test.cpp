// A Vulkan context that presents to a GLFW window (run under xvfb-run by ctest): the surface exists, the
// chosen queue can present to it, and it offers the formats and present modes a swapchain needs.
#include <gtest/gtest.h>

#include <vector>

#include "vk/context.h"
#include "window/window.h"

namespace lagoon::test {
namespace {

TEST(WindowContext, PresentsToAGlfwWindow) {
  auto window = Window::create(320, 240, "lagoon window test");
  ASSERT_TRUE(window) << window.error().message;
  vk::ContextOptions options = vk::ContextOptions::from_environment();
  options.validation = true;
  options.instance_extensions = Window::required_instance_extensions();
  ASSERT_FALSE(options.instance_extensions.empty());
  options.create_surface = [&](VkInstance instance) { return (*window)->create_surface(instance); };
  auto ctx = vk::Context::create(options);
  ASSERT_TRUE(ctx) << ctx.error().message;
  vk::Context& c = **ctx;
  ASSERT_NE(c.surface(), VK_NULL_HANDLE);

  VkBool32 present = VK_FALSE;
  ASSERT_EQ(
      vkGetPhysicalDeviceSurfaceSupportKHR(c.physical_device(), c.queue_family(), c.surface(), &present),
      VK_SUCCESS);
  EXPECT_TRUE(present);
  uint32_t formats = 0, modes = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(c.physical_device(), c.surface(), &formats, nullptr);
  vkGetPhysicalDeviceSurfacePresentModesKHR(c.physical_device(), c.surface(), &modes, nullptr);
  EXPECT_GT(formats, 0u);
  EXPECT_GT(modes, 0u);
  const VkExtent2D fb = (*window)->framebuffer_extent();
  EXPECT_EQ(fb.width, 320u);
  EXPECT_EQ(fb.height, 240u);
  EXPECT_EQ(c.validation().failures(), 0u);
}

}  // namespace
}  // namespace lagoon::test
