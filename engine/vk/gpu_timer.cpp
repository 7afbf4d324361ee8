#include "vk/gpu_timer.h"

#include "vk/check.h"
#include "vk/context.h"

namespace lagoon::vk {

GpuTimer::GpuTimer(const Context& ctx, uint32_t max_scopes) : device_(ctx.device()), max_scopes_(max_scopes) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical_device(), &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical_device(), &count, families.data());
  const uint32_t valid_bits = families[ctx.queue_family()].timestampValidBits;
  if (valid_bits == 0 || ctx.properties().limits.timestampPeriod <= 0.0f) return;  // no timing on this queue
  valid_mask_ = valid_bits >= 64 ? ~0ull : ((1ull << valid_bits) - 1);
  ns_per_tick_ = ctx.properties().limits.timestampPeriod;
  const VkQueryPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                   .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                   .queryCount = 2 * max_scopes};
  VkQueryPool pool;
  VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool));
  pool_ = Unique<VkQueryPool>(device_, pool);
}

void GpuTimer::reset(VkCommandBuffer cmd) {
  names_.clear();
  if (pool_) vkCmdResetQueryPool(cmd, pool_, 0, 2 * max_scopes_);
}

uint32_t GpuTimer::begin(VkCommandBuffer cmd, std::string_view name) {
  if (names_.size() >= max_scopes_)
    throw_usage_error("GpuTimer: more than " + std::to_string(max_scopes_) + " scopes");
  const uint32_t scope = static_cast<uint32_t>(names_.size());
  names_.emplace_back(name);
  if (pool_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope);
  return scope;
}

void GpuTimer::end(VkCommandBuffer cmd, uint32_t scope) {
  if (pool_) vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * scope + 1);
}

std::vector<PassTime> GpuTimer::results() const {
  std::vector<PassTime> out;
  if (!pool_ || names_.empty()) return out;
  std::vector<uint64_t> ticks(2 * names_.size());
  VK_CHECK(vkGetQueryPoolResults(device_, pool_, 0, static_cast<uint32_t>(ticks.size()),
                                 ticks.size() * sizeof(uint64_t), ticks.data(), sizeof(uint64_t),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  for (size_t i = 0; i < names_.size(); ++i) {
    const uint64_t delta = ((ticks[2 * i + 1] & valid_mask_) - (ticks[2 * i] & valid_mask_)) & valid_mask_;
    out.push_back({names_[i], double(delta) * ns_per_tick_ * 1e-6});
  }
  return out;
}

}  // namespace lagoon::vk
