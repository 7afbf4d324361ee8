#include "vk/pipeline_cache.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/bounded_file.h"
#include "vk/check.h"

namespace lagoon::vk {
namespace {

bool header_matches(const std::vector<char>& data, const VkPhysicalDeviceProperties& props) {
  VkPipelineCacheHeaderVersionOne header;
  if (data.size() < sizeof(header)) return false;
  std::memcpy(&header, data.data(), sizeof(header));
  return header.headerSize >= sizeof(header) &&
         header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && header.vendorID == props.vendorID &&
         header.deviceID == props.deviceID &&
         std::memcmp(header.pipelineCacheUUID, props.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

}  // namespace

std::string pipeline_cache_file_name(const VkPhysicalDeviceProperties& props) {
  char uuid[2 * VK_UUID_SIZE + 1];
  for (uint32_t i = 0; i < VK_UUID_SIZE; ++i)
    std::snprintf(uuid + 2 * i, 3, "%02x", props.pipelineCacheUUID[i]);
  char name[128];
  std::snprintf(name, sizeof(name), "pipeline-cache-%04x-%04x-%s.bin", props.vendorID, props.deviceID, uuid);
  return name;
}

Unique<VkPipelineCache> load_pipeline_cache(VkDevice device, const VkPhysicalDeviceProperties& props,
                                            const std::filesystem::path& file) {
  std::vector<char> data;
  if (!file.empty()) {
    // A cache is a few MiB; anything else in its place (a FIFO, a huge file) is ignored, not read.
    Result<std::string> bytes = read_bounded_file(file, std::uintmax_t{256} << 20);
    if (bytes) data.assign(bytes->begin(), bytes->end());
    if (!header_matches(data, props)) data.clear();
  }
  const VkPipelineCacheCreateInfo info{.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO,
                                       .initialDataSize = data.size(),
                                       .pInitialData = data.empty() ? nullptr : data.data()};
  VkPipelineCache cache;
  VK_CHECK(vkCreatePipelineCache(device, &info, nullptr, &cache));
  return {device, cache};
}

Result<void> save_pipeline_cache(VkDevice device, VkPipelineCache cache, const std::filesystem::path& file) {
  size_t size = 0;
  VK_CHECK(vkGetPipelineCacheData(device, cache, &size, nullptr));
  std::vector<char> data(size);
  VK_CHECK(vkGetPipelineCacheData(device, cache, &size, data.data()));
  data.resize(size);
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  const std::filesystem::path tmp = file.string() + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) {
      std::filesystem::remove(tmp, ec);
      return make_error("could not write the pipeline cache " + tmp.string() +
                        " (set LAGOON_PIPELINE_CACHE to a writable folder, or to 'off')");
    }
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    return make_error("could not replace the pipeline cache " + file.string() + ": " + ec.message());
  }
  return {};
}

}  // namespace lagoon::vk
