#include "gltf/read_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

namespace lagoon::gltf::detail {

namespace fs = std::filesystem;

Result<std::vector<uint8_t>> read_file(const fs::path& path, size_t max_bytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return make_error("does not exist");
  if (fs::is_directory(status)) return make_error("is a folder, not a glTF file");
  if (!fs::is_regular_file(status)) return make_error("is not a regular file");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) return make_error("cannot be read: " + ec.message());
  if (size > max_bytes) {
    return make_error("has " + std::to_string(size) + " bytes, more than the limit of " +
                      std::to_string(max_bytes) + " (Limits::max_file_bytes)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(std::string("cannot be opened: ") + std::strerror(errno));
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<uintmax_t>(in.gcount()) != size) {
    return make_error("cannot be read (it changed size while being read, or the read failed)");
  }
  return bytes;
}

}  // namespace lagoon::gltf::detail
