#include "vk/frame_ring.h"

#include "vk/check.h"
#include "vk/context.h"

namespace lagoon::vk {

FrameRing::FrameRing(Context& ctx, uint32_t frames_in_flight) : ctx_(ctx), slots_(frames_in_flight) {
  if (frames_in_flight == 0 || frames_in_flight > ctx.deferred().slots())
    throw_usage_error("FrameRing: frames_in_flight must be 1.." + std::to_string(ctx.deferred().slots()) +
                      " (ContextOptions::frames_in_flight)");
  for (Slot& s : slots_) {
    const VkCommandPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                            .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                            .queueFamilyIndex = ctx.queue_family()};
    VkCommandPool pool;
    VK_CHECK(vkCreateCommandPool(ctx.device(), &pool_info, nullptr, &pool));
    s.pool = Unique<VkCommandPool>(ctx.device(), pool);
    const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                            .commandPool = pool,
                                            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                            .commandBufferCount = 1};
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &alloc, &s.cmd));
    // Created signalled so the first begin() of each slot does not wait forever.
    const VkFenceCreateInfo fence_info{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
                                       .flags = VK_FENCE_CREATE_SIGNALED_BIT};
    VkFence fence;
    VK_CHECK(vkCreateFence(ctx.device(), &fence_info, nullptr, &fence));
    s.fence = Unique<VkFence>(ctx.device(), fence);
  }
}

FrameRing::~FrameRing() {
  // Every slot's work must finish before its command pool goes.
  std::vector<VkFence> fences;
  for (Slot& s : slots_) fences.push_back(s.fence);
  vkWaitForFences(ctx_.device(), static_cast<uint32_t>(fences.size()), fences.data(), VK_TRUE, UINT64_MAX);
}

VkCommandBuffer FrameRing::begin() {
  if (recording_) throw_usage_error("FrameRing::begin called twice without submit");
  slot_ = static_cast<uint32_t>(frame_number_ % slots_.size());
  Slot& s = slots_[slot_];
  VkFence fence = s.fence;
  VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
  ctx_.deferred().begin_frame(slot_);
  VK_CHECK(vkResetCommandPool(ctx_.device(), s.pool, 0));
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  VK_CHECK(vkBeginCommandBuffer(s.cmd, &begin));
  recording_ = true;
  return s.cmd;
}

void FrameRing::submit(const FrameSync& sync) {
  if (!recording_) throw_usage_error("FrameRing::submit without begin");
  Slot& s = slots_[slot_];
  VK_CHECK(vkEndCommandBuffer(s.cmd));
  const VkCommandBufferSubmitInfo cmd_info{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                           .commandBuffer = s.cmd};
  const VkSemaphoreSubmitInfo wait{
      .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, .semaphore = sync.wait, .stageMask = sync.wait_stage};
  const VkSemaphoreSubmitInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                     .semaphore = sync.signal,
                                     .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
  const VkSubmitInfo2 submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .waitSemaphoreInfoCount = sync.wait ? 1u : 0u,
                             .pWaitSemaphoreInfos = &wait,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &cmd_info,
                             .signalSemaphoreInfoCount = sync.signal ? 1u : 0u,
                             .pSignalSemaphoreInfos = &signal};
  VkFence fence = s.fence;
  VK_CHECK(vkResetFences(ctx_.device(), 1, &fence));
  VK_CHECK(vkQueueSubmit2(ctx_.queue(), 1, &submit, fence));
  recording_ = false;
  ++frame_number_;
}

void FrameRing::wait_last() {
  if (frame_number_ == 0) return;
  VkFence fence = slots_[(frame_number_ - 1) % slots_.size()].fence;
  VK_CHECK(vkWaitForFences(ctx_.device(), 1, &fence, VK_TRUE, UINT64_MAX));
}

}  // namespace lagoon::vk
