// A GLFW window that Vulkan can present to. The engine is headless by default; the demo adds this.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "core/result.h"

struct GLFWwindow;

namespace lagoon {

class Window {
 public:
  // Fails with a message saying what to do when there is no display (e.g. run under `xvfb-run -a`).
  static Result<std::unique_ptr<Window>> create(uint32_t width, uint32_t height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Instance extensions the surface needs; pass to vk::ContextOptions::instance_extensions.
  static std::vector<std::string> required_instance_extensions();
  // For vk::ContextOptions::create_surface. Returns VK_NULL_HANDLE on failure.
  VkSurfaceKHR create_surface(VkInstance instance) const;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void poll_events() const;
  // Framebuffer size in pixels (0 x 0 while minimised).
  VkExtent2D framebuffer_extent() const;

 private:
  Window() = default;
  GLFWwindow* window_ = nullptr;
};

}  // namespace lagoon
