#include "gltf/read_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

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
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(std::string("cannot be opened: ") + std::strerror(errno));
  std::vector<uint8_t> bytes(static_cast<size_t>(check.size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<uintmax_t>(in.gcount()) != check.size) {
    return make_error("cannot be read (it changed size while being read, or the read failed)");
  }
  return bytes;
}

}  // namespace lagoon::gltf::detail
