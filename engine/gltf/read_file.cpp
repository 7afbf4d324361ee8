#include "gltf/read_file.h"

#include <string>

#include "core/bounded_file.h"

namespace lagoon::gltf::detail {

namespace fs = std::filesystem;

Result<std::vector<uint8_t>> read_file(const fs::path& path, size_t max_bytes) {
  const FileCheck check = check_file_to_read(path, max_bytes);
  switch (check.problem) {
    case FileProblem::kNone:
      break;
    case FileProblem::kFolder:
      return make_error("is a folder, not a glTF file");
    case FileProblem::kTooLarge:
      return make_error("has " + std::to_string(check.size) + " bytes, more than the limit of " +
                        std::to_string(max_bytes) + " (Limits::max_file_bytes)");
    default:
      return make_error(check.reason);
  }
  return read_checked_file<std::vector<uint8_t>>(path, check);
}

}  // namespace lagoon::gltf::detail
