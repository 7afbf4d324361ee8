// The pipeline cache persists between runs (one file per device and driver build), so start-up does not
// recompile every pipeline. A stale or foreign file is ignored, never trusted.
#pragma once
#include <vulkan/vulkan.h>

#include <filesystem>
#include <string>

#include "core/result.h"
#include "vk/handle.h"

namespace lagoon::vk {

// "pipeline-cache-<vendor>-<device>-<uuid>.bin": a driver update changes the UUID, so old files are skipped.
std::string pipeline_cache_file_name(const VkPhysicalDeviceProperties& properties);

// Creates a cache seeded from `file` when it exists and its header matches this device; empty otherwise.
Unique<VkPipelineCache> load_pipeline_cache(VkDevice device, const VkPhysicalDeviceProperties& properties,
                                            const std::filesystem::path& file);

// Writes atomically (temporary file + rename) so a crash never leaves a truncated cache.
Result<void> save_pipeline_cache(VkDevice device, VkPipelineCache cache, const std::filesystem::path& file);

}  // namespace lagoon::vk
