// Whole-file reads with a size limit, for the model file and the buffers and images it names.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/result.h"

namespace lagoon::gltf::detail {

// Only regular files are opened (a FIFO or device would block or never end), and the size is checked
// before reading. The error is the reason only ("does not exist"); the caller names the file.
Result<std::vector<uint8_t>> read_file(const std::filesystem::path& path, size_t max_bytes);

}  // namespace lagoon::gltf::detail
