// One frame of the demo: the clock, the renderer's frame copied into the swapchain image with the UI on top,
// the present, and screenshots (a copy of what the window shows).
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "core/free_heap.h"
#include "demo.h"
#include "io/png.h"
#include "live_clock.h"
#include "shared/caustics.h"
#include "vk/barriers.h"
#include "vk/check.h"

namespace lagoon::demo {

// One pass of the loop; false once the last of --frames was presented and --exit asks to stop there.
bool Demo::frame() {
  const VkExtent2D fb = window_->framebuffer_extent();
  if (fb.width == 0 || fb.height == 0) {  // minimised: nothing to draw into
    glfwWaitEventsTimeout(0.1);
    last_frame_ = Clock::now();
    return true;
  }
  if (swapchain_dirty_ || fb.width != swapchain_->extent().width || fb.height != swapchain_->extent().height)
    recreate_swapchain();
  const float dt = tick();
  if (!last_frame_full_size_) observe_frame_time(dt);
  update_ui(dt);
  const scene::Scene frame_scene = advance_time(dt);

  renderer_->prepare(frame_scene);  // a jump in time warms the foam up here, outside the frame's recording
  VkCommandBuffer cmd = ring_->begin();
  const uint32_t slot = ring_->slot();
  if (slot_used_[slot]) timings_ = renderer_->timings(slot);
  const std::optional<uint32_t> image = acquire_image(slot);
  if (!image) {
    ring_->submit();  // nothing recorded; keeps the ring's slots in step
    swapchain_dirty_ = true;
    return true;
  }
  const bool last_scripted = options_.frames && frame_ + 1 == *options_.frames;
  const std::string screenshot = take_screenshot_request(last_scripted);
  // Scripted runs (what the tests compare with the CLI) and screenshots are drawn at the window's size.
  last_frame_full_size_ = options_.frames || !screenshot.empty() || resolution_.target_fps() == 0;
  record_to_swapchain(cmd, frame_scene, slot, *image, last_frame_full_size_);

  vk::Buffer pixels;
  if (!screenshot.empty()) pixels = record_screenshot_copy(cmd, *image);
  submit_and_present(slot, *image);
  if (frame_ == fail_after_frame_)
    throw vk::VulkanError("vkQueueSubmit (LAGOON_DEMO_FAIL_AFTER_FRAME)", VK_ERROR_DEVICE_LOST);
  if (!screenshot.empty()) finish_screenshot(screenshot, pixels);
  if (last_scripted && !options_.save_scene.empty()) save_scene_to(options_.save_scene);
  ++frame_;
  if (frame_ == 2)
    cold_failures_ += render::ColdCompile::finish(cold_, *ctx_);  // the first frame's code is made
  // Every 64 frames the freed heap goes back to the system: an edit that rebuilds the renderer compiles its
  // pipelines over the next frames and frees what the compiler used.
  if (frame_ % 64 == 0) release_free_heap();
  return !(last_scripted && options_.exit_after_frames);
}

// Feeds the dynamic resolution a live frame's time and says when the size it draws at moves (a line a user
// can match against the timing tab; the live test waits for it instead of guessing how long to run).
uint32_t Demo::live_caustic_cells() const {
  return LAGOON_CAUSTICS_CELLS / uint32_t(resolution_.caustic_coarsening());
}

void Demo::observe_frame_time(float dt) {
  const double before = resolution_.scale();
  resolution_.observe(double(dt) * 1000.0);
  if (resolution_.scale() == before) return;
  const VkExtent2D drawn = resolution_.render_extent(swapchain_->extent());
  const uint32_t cells = live_caustic_cells();
  std::printf(
      "lagoon-demo: live frames now drawn at %.0f %% of the window (%ux%u) for %g frames a second; caustic "
      "map "
      "%u x %u cells\n",
      100.0 * resolution_.scale(), drawn.width, drawn.height, resolution_.target_fps(), cells, cells);
  std::fflush(stdout);
}

// Seconds since the previous frame; the last 240 frames' times feed the timing tab and the summary.
float Demo::tick() {
  const Clock::time_point now = Clock::now();
  const float dt = std::chrono::duration<float>(now - last_frame_).count();
  last_frame_ = now;
  frame_ms_.push_back(dt * 1000.0f);
  if (frame_ms_.size() > 240) frame_ms_.pop_front();
  return dt;
}

// Input, this frame's script steps and the panel, ending the ImGui frame; then a rebuild if edits need one.
void Demo::update_ui(float dt) {
  ui_->new_frame();
  handle_input(dt);
  if (options_.frames && frame_ != scripted_frame_) {  // once per frame, even if the frame is retried
    apply_script(frame_);
    scripted_frame_ = frame_;
  }
  draw_ui();
  ImGui::Render();
  rebuild_after_edits();
}

// The scene at this frame's time: exactly 1/fps per frame in scripted runs, the wall clock otherwise (at most
// a quarter of a second a frame: live_clock.h).
scene::Scene Demo::advance_time(float dt) {
  const double from = time_s_;
  if (options_.frames) {
    time_s_ = t0_ + double(frame_) / options_.fps;
  } else if (!paused_) {
    time_s_ += live_step_s(dt);
  } else if (step_once_) {
    time_s_ += 1.0 / 30.0;
  }
  step_once_ = false;
  time_s_ = std::min(time_s_, 86400.0);
  steer(from, std::max(time_s_ - from, 0.0));
  scene::Scene frame_scene = scene_;
  frame_scene.time_s = float(time_s_);
  return frame_scene;
}

// The next swapchain image (signalling acquired_[slot]); nullopt when the swapchain is out of date.
std::optional<uint32_t> Demo::acquire_image(uint32_t slot) {
  uint32_t image = 0;
  const VkResult acquire = vkAcquireNextImageKHR(ctx_->device(), swapchain_->handle(), UINT64_MAX,
                                                 acquired_[slot], VK_NULL_HANDLE, &image);
  if (acquire == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
  if (acquire != VK_SUCCESS && acquire != VK_SUBOPTIMAL_KHR) VK_CHECK(acquire);
  return image;
}

// The renderer's frame, then the rendered frame into the swapchain image (a blit converts RGBA to the
// swapchain's BGRA, and stretches a frame drawn at the dynamic resolution to the window), then the UI over
// it, which leaves the image ready to present.
void Demo::record_to_swapchain(VkCommandBuffer cmd, const scene::Scene& frame_scene, uint32_t slot,
                               uint32_t image, bool full_size) {
  const VkExtent2D extent = swapchain_->extent();
  const VkExtent2D drawn = full_size ? extent : resolution_.render_extent(extent);
  renderer_->set_caustic_cells(full_size ? LAGOON_CAUSTICS_CELLS : live_caustic_cells());
  const vk::Image& colour = renderer_->record(cmd, frame_scene, drawn, slot);
  slot_used_[slot] = true;

  const VkImage target = swapchain_->image(image);
  const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  const vk::Access acquired_stage{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE};
  vk::image_barrier(cmd, colour.handle(), colour.all_subresources(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, vk::access::kColorAttachmentWrite,
                    vk::access::kTransferRead);
  vk::image_barrier(cmd, target, whole, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    acquired_stage, vk::access::kTransferWrite);
  const VkImageBlit region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                           .srcOffsets = {{0, 0, 0}, {int32_t(drawn.width), int32_t(drawn.height), 1}},
                           .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                           .dstOffsets = {{0, 0, 0}, {int32_t(extent.width), int32_t(extent.height), 1}}};
  vkCmdBlitImage(
      cmd, colour.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region,
      drawn.width == extent.width && drawn.height == extent.height ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
  vk::image_barrier(cmd, colour.handle(), colour.all_subresources(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kTransferRead,
                    vk::access::kColorAttachmentWrite);
  ui_->record(cmd, image, ImGui::GetDrawData());
}

// The file this frame's screenshot goes to, or empty: F12 or the panel's button, or --screenshot on the last
// of --frames (on the first frame without --frames).
std::string Demo::take_screenshot_request(bool last_scripted) {
  std::string screenshot = std::move(screenshot_request_);
  screenshot_request_.clear();
  if (!options_.screenshot.empty() && (last_scripted || (!options_.frames && frame_ == 0)))
    screenshot = options_.screenshot;
  return screenshot;
}

// A screenshot is what the window shows: the swapchain image after the UI, copied to a host-readable buffer.
vk::Buffer Demo::record_screenshot_copy(VkCommandBuffer cmd, uint32_t image) {
  const VkExtent2D extent = swapchain_->extent();
  const VkImage target = swapchain_->image(image);
  const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vk::Buffer pixels =
      vk::Buffer::create(*ctx_, VkDeviceSize(extent.width) * extent.height * 4,
                         VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback, "screenshot");
  vk::image_barrier(cmd, target, whole, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    vk::access::kColorAttachmentWrite, vk::access::kTransferRead);
  const VkBufferImageCopy copy{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                               .imageExtent = {extent.width, extent.height, 1}};
  vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pixels.handle(), 1, &copy);
  vk::image_barrier(cmd, target, whole, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                    vk::access::kTransferRead, vk::access::kNone);
  vk::buffer_barrier(cmd, pixels.handle(), vk::access::kTransferWrite, vk::access::kHostRead);
  return pixels;
}

// Submits the slot's commands (after the image is acquired) and presents once they are done; a swapchain
// that no longer fits the window is recreated next frame.
void Demo::submit_and_present(uint32_t slot, uint32_t image) {
  ring_->submit({.wait = acquired_[slot],
                 .wait_stage = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                 .signal = swapchain_->rendered(image)});
  const VkSemaphore rendered = swapchain_->rendered(image);
  const VkSwapchainKHR swapchain = swapchain_->handle();
  const VkPresentInfoKHR present{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                                 .waitSemaphoreCount = 1,
                                 .pWaitSemaphores = &rendered,
                                 .swapchainCount = 1,
                                 .pSwapchains = &swapchain,
                                 .pImageIndices = &image};
  const VkResult presented = vkQueuePresentKHR(ctx_->queue(), &present);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR)
    swapchain_dirty_ = true;
  else
    VK_CHECK(presented);
}

// Waits for the frame, then writes its copy; a --screenshot that cannot be written makes the exit code 1.
void Demo::finish_screenshot(const std::string& path, const vk::Buffer& pixels) {
  ring_->wait_last();
  if (auto r = save_screenshot(path, pixels); !r) {
    message(r.error().message);
    if (path == options_.screenshot) exit_status_ = cli::kExitFailure;
  } else {
    message("wrote " + path + " (t = " + std::to_string(time_s_) + " s)");
  }
}

Result<void> Demo::save_screenshot(const std::string& path, const vk::Buffer& pixels) const {
  const VkExtent2D e = swapchain_->extent();
  io::Image8 image;
  image.width = e.width;
  image.height = e.height;
  image.rgba.resize(size_t(e.width) * e.height * 4);
  pixels.invalidate();
  std::memcpy(image.rgba.data(), pixels.mapped(), image.rgba.size());
  if (swapchain_->format() == VK_FORMAT_B8G8R8A8_UNORM)
    for (size_t i = 0; i < image.rgba.size(); i += 4) std::swap(image.rgba[i], image.rgba[i + 2]);
  return io::write_png(path, image);
}

void Demo::recreate_swapchain() {
  ctx_->wait_idle();
  // The window may have been minimised since the loop looked: try again next frame.
  VkSurfaceCapabilitiesKHR caps{};
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_->physical_device(), ctx_->surface(), &caps));
  if (caps.currentExtent.width == 0 || caps.currentExtent.height == 0) return;
  auto next = std::make_unique<Swapchain>(*ctx_, window_->framebuffer_extent(), vsync_, swapchain_.get());
  swapchain_ = std::move(next);
  ui_->on_swapchain(*swapchain_);
  swapchain_dirty_ = false;
}

}  // namespace lagoon::demo
