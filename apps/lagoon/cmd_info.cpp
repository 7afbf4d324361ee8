// lagoon info: which device Lagoon picks and the limits that matter for its passes.
#include <cstdio>
#include <string>
#include <vector>

#include "commands.h"
#include "gpu_session.h"
#include "vk/device_select.h"

namespace lagoon::cli {
namespace {

int run_info(const ParsedArgs&) {
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  const auto& info = ctx->device_info();
  const VkPhysicalDeviceLimits& l = ctx->properties().limits;
  VkPhysicalDeviceSubgroupProperties subgroup{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 props{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                    .pNext = &subgroup};
  vkGetPhysicalDeviceProperties2(ctx->physical_device(), &props);

  std::printf("device            %s (%s), index %u\n", info.name.c_str(), info.type.c_str(), info.index);
  std::printf("driver            %s %s, version %s\n", info.driver_name.c_str(), info.driver_info.c_str(),
              info.driver_version.c_str());
  std::printf("vulkan api        %s\n", vk::api_version_string(info.api_version).c_str());
  std::printf("validation        %s\n",
              ctx->validation_enabled() ? "on" : "off (LAGOON_VALIDATION=1 turns it on)");
  std::printf("pipeline cache    %s\n",
              ctx->pipeline_cache_file().empty() ? "not persisted" : ctx->pipeline_cache_file().c_str());
  std::printf("limits\n");
  std::printf("  max image 2D                 %u\n", l.maxImageDimension2D);
  std::printf("  max image array layers       %u\n", l.maxImageArrayLayers);
  std::printf("  max compute workgroup        %u x %u x %u, %u invocations\n", l.maxComputeWorkGroupSize[0],
              l.maxComputeWorkGroupSize[1], l.maxComputeWorkGroupSize[2], l.maxComputeWorkGroupInvocations);
  std::printf("  max compute shared memory    %u bytes\n", l.maxComputeSharedMemorySize);
  std::printf("  max storage buffer range     %u bytes\n", l.maxStorageBufferRange);
  std::printf("  max push constants           %u bytes\n", l.maxPushConstantsSize);
  std::printf("  max sampler anisotropy       %.0f\n", l.maxSamplerAnisotropy);
  std::printf("  subgroup size                %u\n", subgroup.subgroupSize);
  std::printf("  timestamp period             %.3f ns (compute and graphics: %s)\n", l.timestampPeriod,
              l.timestampComputeAndGraphics ? "yes" : "no");
  const auto& mem = ctx->memory_properties();
  for (uint32_t i = 0; i < mem.memoryHeapCount; ++i)
    std::printf("  memory heap %u                %.1f MiB%s\n", i,
                double(mem.memoryHeaps[i].size) / (1 << 20),
                mem.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT ? " (device local)" : "");
  return validation_status(*ctx);
}

}  // namespace

const Command& info_command() {
  static const Command command{
      .spec = {.name = "info",
               .summary = "Prints the Vulkan device Lagoon uses, its driver, API version and the limits that "
                          "matter for the ocean passes.",
               .options = {},
               .details =
                   "environment:\n"
                   "  LAGOON_DEVICE=<index|name>  choose a device (default: discrete > integrated > virtual "
                   "> CPU)\n"
                   "  LAGOON_VALIDATION=1         enable the Vulkan validation layer; errors make the exit "
                   "code 3\n"
                   "  LAGOON_PIPELINE_CACHE=DIR   where the pipeline cache persists ('off' disables)\n"},
      .run = run_info};
  return command;
}

}  // namespace lagoon::cli
