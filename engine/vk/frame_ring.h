// Frames in flight: each slot has its command buffer, its fence and its share of the deferred-destroy
// list. begin() waits for the slot's previous use, then frees what was deferred during it.
#pragma once
#include <vulkan/vulkan.h>

#include <vector>

#include "vk/handle.h"

namespace lagoon::vk {

class Context;

struct FrameSync {
  VkSemaphore wait = VK_NULL_HANDLE;  // e.g. swapchain image acquired
  VkPipelineStageFlags2 wait_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSemaphore signal = VK_NULL_HANDLE;  // e.g. ready to present
};

class FrameRing {
 public:
  FrameRing(Context& ctx, uint32_t frames_in_flight);
  ~FrameRing();
  FrameRing(const FrameRing&) = delete;
  FrameRing& operator=(const FrameRing&) = delete;

  // Waits for this slot's previous frame, flushes its deferred objects, returns a command buffer in the
  // recording state.
  VkCommandBuffer begin();
  // Ends and submits the command buffer; the slot's fence signals when the GPU is done with it.
  void submit(const FrameSync& sync = {});
  // Waits for the frame just submitted (headless rendering reads its result at once).
  void wait_last();

  uint32_t slot() const { return slot_; }
  uint32_t frames_in_flight() const { return static_cast<uint32_t>(slots_.size()); }
  uint64_t frame_number() const { return frame_number_; }

 private:
  struct Slot {
    Unique<VkCommandPool> pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    Unique<VkFence> fence;
  };
  Context& ctx_;
  std::vector<Slot> slots_;
  uint32_t slot_ = 0;
  uint64_t frame_number_ = 0;
  bool recording_ = false;
};

}  // namespace lagoon::vk
