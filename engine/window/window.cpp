#include "window/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cstdio>
#include <mutex>

namespace lagoon {
namespace {

std::string& last_glfw_error() {
  static std::string error;
  return error;
}

// glfwInit is process-wide; it stays initialised until exit (glfwTerminate at exit would race other windows).
Result<void> init_glfw() {
  static std::once_flag once;
  static bool ok = false;
  std::call_once(once, [] {
    glfwSetErrorCallback(
        [](int code, const char* text) { last_glfw_error() = std::to_string(code) + ": " + text; });
    ok = glfwInit() == GLFW_TRUE;
    if (ok) std::atexit(glfwTerminate);
  });
  if (!ok)
    return make_error("cannot open a window: GLFW failed to initialise (" + last_glfw_error() +
                      "). Is there a display? Set DISPLAY, or run headless under 'xvfb-run -a'.");
  if (!glfwVulkanSupported())
    return make_error("GLFW found no Vulkan loader; install libvulkan1 and mesa-vulkan-drivers");
  return {};
}

}  // namespace

Result<std::unique_ptr<Window>> Window::create(uint32_t width, uint32_t height, const std::string& title) {
  if (auto r = init_glfw(); !r) return r.error();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, not OpenGL
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  std::unique_ptr<Window> w(new Window());
  w->window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!w->window_)
    return make_error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                      " window: " + last_glfw_error());
  return w;
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
}

std::vector<std::string> Window::required_instance_extensions() {
  if (!init_glfw()) return {};
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  if (glfwCreateWindowSurface(instance, window_, nullptr, &surface) != VK_SUCCESS) return VK_NULL_HANDLE;
  return surface;
}

bool Window::should_close() const {
  return glfwWindowShouldClose(window_);
}
void Window::poll_events() const {
  glfwPollEvents();
}

VkExtent2D Window::framebuffer_extent() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {uint32_t(w), uint32_t(h)};
}

}  // namespace lagoon
