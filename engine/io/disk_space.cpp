#include "io/disk_space.h"

#include <cstdio>
#include <system_error>

namespace lagoon::io {

namespace fs = std::filesystem;

Result<uint64_t> available_bytes(const fs::path& path) {
  std::error_code ec;
  fs::path probe = fs::absolute(path, ec);
  if (ec) return make_error("cannot resolve " + path.string() + ": " + ec.message());
  while (!fs::exists(probe, ec) && probe.has_relative_path()) probe = probe.parent_path();
  const fs::space_info space = fs::space(probe, ec);
  if (ec) return make_error("cannot tell the free space at " + probe.string() + ": " + ec.message());
  return uint64_t(space.available);
}

std::string format_bytes(uint64_t bytes) {
  static const char* const units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 5) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}

}  // namespace lagoon::io
