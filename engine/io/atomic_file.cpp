#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>
#include <utility>

namespace lagoon::io {
namespace {

// Distinguishes temporaries of concurrent writers to the same target inside one process.
std::atomic<uint64_t> g_temp_counter{0};

class FdCloser {
 public:
  explicit FdCloser(int fd) : fd_(fd) {}
  ~FdCloser() {
    if (fd_ >= 0) ::close(fd_);
  }
  FdCloser(const FdCloser&) = delete;
  FdCloser& operator=(const FdCloser&) = delete;

 private:
  int fd_;
};

// Makes the rename itself durable. Best effort: the new file is already complete and visible, and some
// file systems refuse fsync on directories.
void sync_directory(const std::filesystem::path& dir) {
  int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

std::string os_error_message(const char* what, const std::filesystem::path& path, int errnum) {
  return std::string(what) + " " + path.string() + ": " + std::generic_category().message(errnum);
}

Result<AtomicFile> AtomicFile::create(const std::filesystem::path& target) {
  if (target.filename().empty()) return make_error("cannot write " + target.string() + ": not a file name");
  const std::filesystem::path dir = target.parent_path();
  if (!dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
      return make_error("cannot write " + target.string() + ": cannot create folder " + dir.string() + ": " +
                        ec.message());
    }
  }
  const std::string temp_name = target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                                std::to_string(g_temp_counter.fetch_add(1));
  std::filesystem::path temp = dir / temp_name;
  // O_EXCL: never adopt (and later delete) a file someone else created under the same name.
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return make_error(os_error_message("cannot write", target, errno));
  return AtomicFile(target, std::move(temp), fd);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temp_(std::move(other.temp_)),
      fd_(std::exchange(other.fd_, -1)),
      failed_(other.failed_) {
  other.temp_.clear();  // the moved-from object must not delete our temporary
}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    target_ = std::move(other.target_);
    temp_ = std::move(other.temp_);
    fd_ = std::exchange(other.fd_, -1);
    failed_ = other.failed_;
    other.temp_.clear();
  }
  return *this;
}

AtomicFile::~AtomicFile() {
  discard();
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
}

Error AtomicFile::fail(const char* what, int errnum) {
  failed_ = true;
  return make_error(os_error_message(what, target_, errnum));
}

Result<void> AtomicFile::write(std::span<const std::byte> bytes) {
  if (fd_ < 0) return make_error("cannot write " + target_.string() + ": file already committed or closed");
  if (failed_) return make_error("cannot write " + target_.string() + ": an earlier write failed");
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail("cannot write", errno);
    }
    bytes = bytes.subspan(static_cast<size_t>(n));
  }
  return {};
}

Result<void> AtomicFile::commit() {
  if (fd_ < 0) return make_error("cannot commit " + target_.string() + ": already committed or closed");
  if (failed_) {
    discard();
    return make_error("cannot commit " + target_.string() + ": an earlier write failed");
  }
  // fsync before rename: otherwise a crash can leave the new name pointing at an empty file.
  if (::fsync(fd_) != 0) {
    Error error = fail("cannot write", errno);
    discard();
    return error;
  }
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) {
    Error error = fail("cannot write", errno);
    discard();
    return error;
  }
  if (::rename(temp_.c_str(), target_.c_str()) != 0) {
    Error error = fail("cannot replace", errno);
    discard();
    return error;
  }
  temp_.clear();  // now the target's name; nothing left to clean up
  sync_directory(target_.parent_path());
  return {};
}

Result<void> write_text_atomic(const std::filesystem::path& path, std::string_view text) {
  return write_file_atomic(path, std::as_bytes(std::span(text.data(), text.size())));
}

Result<void> write_file_atomic(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  Result<AtomicFile> file = AtomicFile::create(path);
  if (!file) return file.error();
  if (Result<void> r = file->write(bytes); !r) return r;
  return file->commit();
}

Result<std::vector<std::byte>> read_file_bytes(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer before fstat can refuse it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return make_error(os_error_message("cannot read", path, errno));
  FdCloser closer(fd);
  struct stat st {};
  if (::fstat(fd, &st) != 0) return make_error(os_error_message("cannot read", path, errno));
  if (S_ISDIR(st.st_mode)) return make_error(os_error_message("cannot read", path, EISDIR));
  if (!S_ISREG(st.st_mode))
    return make_error("cannot read " + path.string() +
                      ": not a regular file (a device, pipe or socket, which could block or never end)");
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes)
    return make_error("cannot read " + path.string() + ": it has " + std::to_string(size) +
                      " bytes, more than the " + std::to_string(max_bytes >> 20) +
                      " MiB such a file may have");
  // One byte more than the size, so that a file growing while it is read is noticed, not cut.
  std::vector<std::byte> data(static_cast<size_t>(size) + 1);
  size_t used = 0;
  while (used < data.size()) {
    const ssize_t n = ::read(fd, data.data() + used, data.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      return make_error(os_error_message("cannot read", path, errno));
    }
    if (n == 0) break;
    used += static_cast<size_t>(n);
  }
  if (used != size) return make_error("cannot read " + path.string() + ": it changed size while being read");
  data.resize(used);
  return data;
}

}  // namespace lagoon::io
