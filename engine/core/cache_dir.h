// The folder Lagoon keeps its caches in between runs (the pipeline cache, the water LUTs, the PBR tables, the
// environment map): LAGOON_PIPELINE_CACHE if set ('off': none), else $XDG_CACHE_HOME/lagoon, else
// ~/.cache/lagoon. Empty when caching is off or there is no home.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

namespace lagoon {

inline std::filesystem::path cache_dir_from_environment() {
  auto env = [](const char* name) -> std::string {
    const char* v = std::getenv(name);
    return v ? v : "";
  };
  if (std::string dir = env("LAGOON_PIPELINE_CACHE"); !dir.empty()) return dir == "off" ? "" : dir;
  if (std::string xdg = env("XDG_CACHE_HOME"); !xdg.empty()) return std::filesystem::path(xdg) / "lagoon";
  if (std::string home = env("HOME"); !home.empty()) return std::filesystem::path(home) / ".cache" / "lagoon";
  return "";
}

}  // namespace lagoon
