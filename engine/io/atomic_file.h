// Whole-file I/O primitives. AtomicFile makes output all-or-nothing: readers (and a crash or an error
// half-way) see either the old file or the complete new one, never a truncated image or array.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "core/result.h"

namespace lagoon::io {

// Writes go to "<dir>/<name>.tmp-<pid>-<counter>" next to the target (same file system, so rename() is
// atomic); commit() fsyncs and renames it over the target. Without a successful commit() the destructor
// deletes the temporary, so an early return on error leaves nothing behind.
class AtomicFile {
 public:
  // Creates missing parent folders of `target`, then the temporary file.
  static Result<AtomicFile> create(const std::filesystem::path& target);

  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&& other) noexcept;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  // After a failed write() every later write() and commit() fails too, so one check at commit() suffices.
  Result<void> write(std::span<const std::byte> bytes);
  Result<void> commit();

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temp_path() const { return temp_; }

 private:
  AtomicFile(std::filesystem::path target, std::filesystem::path temp, int fd)
      : target_(std::move(target)), temp_(std::move(temp)), fd_(fd) {}
  void discard() noexcept;
  Error fail(const char* what, int errnum);

  std::filesystem::path target_;
  std::filesystem::path temp_;
  int fd_ = -1;
  bool failed_ = false;
};

// create() + write() + commit() in one call.
Result<void> write_file_atomic(const std::filesystem::path& path, std::span<const std::byte> bytes);
// The same for text (JSON, CSV, Markdown).
Result<void> write_text_atomic(const std::filesystem::path& path, std::string_view text);

// Reads a whole regular file of at most `max_bytes`; the error names the path and the reason. A device,
// pipe or socket is refused before a byte is read (it could block, or never end: issue 36), and so is a
// file larger than the limit.
inline constexpr std::uintmax_t kMaxReadBytes = std::uintmax_t{1} << 30;
Result<std::vector<std::byte>> read_file_bytes(const std::filesystem::path& path,
                                               std::uintmax_t max_bytes = kMaxReadBytes);

// "<what> <path>: <strerror(errnum)>", the shape of every I/O error message here.
std::string os_error_message(const char* what, const std::filesystem::path& path, int errnum);

}  // namespace lagoon::io
