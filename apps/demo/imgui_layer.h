// Dear ImGui on the swapchain: the GLFW and Vulkan backends of libimgui-dev (1.86, which needs a render
// pass), drawn over the rendered frame in the swapchain image. The render pass takes the image from the
// copy (TRANSFER_DST) to PRESENT_SRC, so it runs every frame, with or without a panel.
#pragma once
#include <vulkan/vulkan.h>

#include <vector>

#include "vk/context.h"
#include "vk/handle.h"
#include "window/swapchain.h"
#include "window/window.h"

struct ImDrawData;

namespace lagoon::demo {

class ImGuiLayer {
 public:
  ImGuiLayer(vk::Context& ctx, const Window& window, const Swapchain& swapchain);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // After the swapchain was recreated (the format stays; sizes and image count may change).
  void on_swapchain(const Swapchain& swapchain);
  void new_frame();
  // Ends the ImGui frame and draws it (null: nothing) into swapchain image `image`, leaving it in
  // PRESENT_SRC_KHR; the image must be in TRANSFER_DST_OPTIMAL after a transfer write.
  void record(VkCommandBuffer cmd, uint32_t image, ImDrawData* draw_data);

 private:
  void create_descriptor_pool();
  void create_render_pass(VkFormat format);
  void create_framebuffers(const Swapchain& swapchain);
  void init_backends(const Window& window, const Swapchain& swapchain);
  vk::Context& ctx_;
  vk::Unique<VkDescriptorPool> pool_;
  vk::Unique<VkRenderPass> render_pass_;
  std::vector<vk::Unique<VkFramebuffer>> framebuffers_;
  VkExtent2D extent_{};
};

}  // namespace lagoon::demo
