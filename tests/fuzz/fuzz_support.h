// Shared by the fuzz targets: a private scratch folder per process (the loaders read files, so inputs are
// written there first) and splitting an input at a separator byte.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace lagoon::fuzz {

inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("lagoon-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  // Removed when the fuzzer exits (libFuzzer ends with exit()), so runs do not pile folders up. Registered
  // after `dir` is made, so it runs before `dir` is destroyed.
  [[maybe_unused]] static const int cleanup = std::atexit([] {
    std::error_code ec;
    std::filesystem::remove_all(scratch(), ec);
  });
  return dir;
}

inline std::filesystem::path write_scratch(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = scratch() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  return path;
}

inline std::vector<std::string_view> split(std::string_view data, char separator) {
  std::vector<std::string_view> parts;
  for (size_t start = 0;;) {
    const size_t end = data.find(separator, start);
    parts.push_back(data.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace lagoon::fuzz
