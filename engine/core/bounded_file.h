// Whole-file reads that are bounded before they start (issue 36): only a regular file is read (a FIFO would
// block, /dev/zero would never end, a folder fails late), and its size is checked before the first byte, so
// a wrong file costs nothing. The reasons name no file: the caller names it and says what to do.
#pragma once
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "core/result.h"

namespace lagoon {

enum class FileProblem { kNone, kMissing, kFolder, kNotRegular, kTooLarge, kUnreadable };

struct FileCheck {
  FileProblem problem = FileProblem::kNone;
  std::uintmax_t size = 0;  // bytes, when it is a regular file
  std::string reason;       // "does not exist", "is a folder", ...; empty when there is no problem
  explicit operator bool() const { return problem == FileProblem::kNone; }
};

// "16 MiB", "512 KiB", "300 bytes": a limit as people write it.
inline std::string byte_count(std::uintmax_t bytes) {
  if (bytes >= (std::uintmax_t{1} << 20) && bytes % (std::uintmax_t{1} << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= 1024 && bytes % 1024 == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

// What stands in the way of reading `path` whole, at most `max_bytes` of it; nothing is opened.
inline FileCheck check_file_to_read(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return {FileProblem::kMissing, 0, "does not exist"};
  if (fs::is_directory(status)) return {FileProblem::kFolder, 0, "is a folder, not a file"};
  if (!fs::is_regular_file(status))
    return {FileProblem::kNotRegular, 0,
            "is not a regular file (a device, pipe or socket, which could block or never end)"};
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return {FileProblem::kUnreadable, 0, "cannot be read: " + ec.message()};
  if (size > max_bytes)
    return {FileProblem::kTooLarge, size,
            "has " + std::to_string(size) + " bytes, more than the " + byte_count(max_bytes) +
                " such a file may have"};
  return {FileProblem::kNone, size, ""};
}

// The whole of a file check_file_to_read has passed (`check` is its answer), as `Bytes` (std::string or a
// vector of bytes); the error says why the read failed.
template <typename Bytes = std::string>
Result<Bytes> read_checked_file(const std::filesystem::path& path, const FileCheck& check) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return make_error(std::string("cannot be opened: ") + std::strerror(errno));
  Bytes bytes(static_cast<size_t>(check.size), typename Bytes::value_type{});
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::uintmax_t>(in.gcount()) != check.size || in.bad() ||
      in.peek() != std::ifstream::traits_type::eof())
    return make_error("cannot be read (it changed size while being read, or the disk failed)");
  return bytes;
}

// The whole of a regular file of at most `max_bytes`; the error is check_file_to_read's reason, or why the
// read failed.
template <typename Bytes = std::string>
Result<Bytes> read_bounded_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  const FileCheck check = check_file_to_read(path, max_bytes);
  if (!check) return make_error(check.reason);
  return read_checked_file<Bytes>(path, check);
}

}  // namespace lagoon
