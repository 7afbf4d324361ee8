#include "render/device_key.h"

#include <fstream>
#include <span>
#include <string>

#include "io/sha256.h"

namespace lagoon::render {
namespace {

// A CPU device runs the code LLVM generated for this host's instruction set (with FMA or without), so its
// results are only the same on a CPU with the same features: a cache folder shared by several machines (a
// home directory on a cluster's network file system) must not hand one CPU's foam to another.
const std::string& host_cpu_features() {
  static const std::string digest = [] {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("flags", 0) == 0)
        return io::sha256_hex(std::as_bytes(std::span(line.data(), line.size())));
    return std::string("unknown");
  }();
  return digest;
}

}  // namespace

void add_device(io::ResultKey& key, const vk::Context& ctx) {
  const vk::DeviceInfo& device = ctx.device_info();
  key.add("device", device.name)
      .add("driver", device.driver_info)
      .add("driver_version", device.driver_version);
  if (device.type == "CPU") key.add("host_cpu", host_cpu_features());
}

}  // namespace lagoon::render
