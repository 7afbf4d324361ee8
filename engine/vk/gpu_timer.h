// Per-pass GPU timing with timestamp queries. Record scopes into a frame, read them after its fence.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <string_view>
#include <vector>

#include "vk/handle.h"

namespace lagoon::vk {

class Context;

struct PassTime {
  std::string name;
  double ms = 0.0;
};

class GpuTimer {
 public:
  GpuTimer() = default;
  GpuTimer(const Context& ctx, uint32_t max_scopes = 32);

  bool supported() const { return pool_ != VK_NULL_HANDLE; }
  void reset(VkCommandBuffer cmd);  // once per frame, before the first scope
  uint32_t begin(VkCommandBuffer cmd, std::string_view name);
  void end(VkCommandBuffer cmd, uint32_t scope);
  // The frame's scopes in recording order; call after the frame's fence. Empty when unsupported.
  std::vector<PassTime> results() const;

 private:
  Unique<VkQueryPool> pool_;
  VkDevice device_ = VK_NULL_HANDLE;
  double ns_per_tick_ = 1.0;
  uint64_t valid_mask_ = ~0ull;
  uint32_t max_scopes_ = 0;
  std::vector<std::string> names_;
};

// RAII scope: GpuScope s(timer, cmd, "fft"); a null timer records nothing (timing is optional everywhere).
class GpuScope {
 public:
  GpuScope(GpuTimer* timer, VkCommandBuffer cmd, std::string_view name)
      : timer_(timer), cmd_(cmd), scope_(timer ? timer->begin(cmd, name) : 0) {}
  GpuScope(GpuTimer& timer, VkCommandBuffer cmd, std::string_view name) : GpuScope(&timer, cmd, name) {}
  ~GpuScope() {
    if (timer_) timer_->end(cmd_, scope_);
  }
  GpuScope(const GpuScope&) = delete;
  GpuScope& operator=(const GpuScope&) = delete;

 private:
  GpuTimer* timer_;
  VkCommandBuffer cmd_;
  uint32_t scope_;
};

}  // namespace lagoon::vk
