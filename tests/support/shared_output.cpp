#include "support/shared_output.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <span>
#include <vector>

#include "io/sha256.h"

namespace lagoon::test {
namespace fs = std::filesystem;

namespace {

// Held for the lifetime of the object: other processes asking for the same output wait.
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

std::string binary_identity() {
  std::error_code ec;
  const auto size = fs::file_size(LAGOON_BINARY, ec);
  const auto time = fs::last_write_time(LAGOON_BINARY, ec).time_since_epoch().count();
  return std::to_string(size) + "@" + std::to_string(time);
}

// The shipped scenes and their assets (656 KiB): the outputs shared so far are renders of them, and a
// changed scene must not reuse a render of the old one.
std::string scenes_identity() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(LAGOON_SOURCE_DIR) / "scenes"))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::string all;
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    all += file.string() + "\n" + std::string(std::istreambuf_iterator<char>(in), {});
  }
  return io::sha256_hex(std::as_bytes(std::span(all.data(), all.size())));
}

}  // namespace

fs::path shared_output(const std::string& key, const std::function<bool(const fs::path&)>& make) {
  const std::string text = key + "\nlagoon=" + binary_identity() + "\nscenes=" + scenes_identity();
  const std::string digest = io::sha256_hex(std::as_bytes(std::span(text.data(), text.size())));
  const fs::path root = fs::path(LAGOON_TEST_ARTIFACTS) / "shared";
  fs::create_directories(root);
  const std::string name = digest.substr(0, 24);
  const fs::path dir = root / name, done = root / (name + ".complete");  // the marker beside, not inside
  FileLock lock(root / (name + ".lock"));
  if (fs::exists(done)) return dir;
  fs::remove_all(dir);
  fs::create_directories(dir);
  if (!make(dir) || ::testing::Test::HasFailure()) {
    fs::remove_all(dir);
    return {};
  }
  std::ofstream(done) << key << "\n";
  return dir;
}

}  // namespace lagoon::test
