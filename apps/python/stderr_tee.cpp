#include "stderr_tee.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <stdexcept>

namespace lagoon::python {
namespace {

constexpr size_t kKeep = 64 * 1024;  // an error message is at its end; progress lines may be many

void write_all(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // stderr closed: the copy is still kept
    data += n;
    size -= size_t(n);
  }
}

}  // namespace

StderrTee::StderrTee() {
  int fds[2];
  std::fflush(stderr);
  saved_ = ::dup(2);
  if (saved_ < 0 || ::pipe(fds) != 0) {
    if (saved_ >= 0) ::close(saved_);
    throw std::runtime_error("cannot redirect stderr to read a command's messages");
  }
  read_ = fds[0];
  write_ = fds[1];
  ::dup2(write_, 2);
  reader_ = std::thread([this] {
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(read_, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return;
      write_all(saved_, buffer, size_t(n));
      std::lock_guard lock(mutex_);
      text_.append(buffer, size_t(n));
      if (text_.size() > 2 * kKeep) text_.erase(0, text_.size() - kKeep);
    }
  });
}

std::string StderrTee::finish() {
  if (!finished_) {
    finished_ = true;
    std::fflush(stderr);
    ::dup2(saved_, 2);  // the pipe's last writer is now write_ alone
    ::close(write_);
    reader_.join();
    ::close(read_);
    ::close(saved_);
  }
  std::lock_guard lock(mutex_);
  return text_.size() > kKeep ? text_.substr(text_.size() - kKeep) : text_;
}

StderrTee::~StderrTee() {
  finish();
}

}  // namespace lagoon::python
