#include "io/result_cache.h"

#include <algorithm>
#include <cstdio>

#include "core/cache_dir.h"
#include "io/atomic_file.h"
#include "io/sha256.h"

namespace lagoon::io {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kResultMagic = "lagoon-result 1\n";
constexpr size_t kResultHeader =
    kResultMagic.size() + 2 * 65;  // key digest and payload digest, each 64 hex + '\n'

std::span<const std::byte> as_bytes(std::string_view text) {
  return std::as_bytes(std::span(text.data(), text.size()));
}

std::string digest_of(const ResultKey& key) {
  return sha256_hex(as_bytes(std::string(key.kind()) + '\n' + key.text()));
}

// Keeps the newest max_kept - 1 files of a kind, so storing one more stays within the bound.
void evict_oldest(const fs::path& dir, std::string_view kind, size_t max_kept) {
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::path>> files;
  const std::string prefix = std::string(kind) + "-";
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && entry.path().extension() == ".bin")
      files.emplace_back(entry.last_write_time(ec), entry.path());
  }
  if (files.size() < max_kept) return;
  std::sort(files.begin(), files.end());
  for (size_t i = 0; i + max_kept - 1 < files.size(); ++i) fs::remove(files[i].second, ec);
}

}  // namespace

ResultKey::ResultKey(std::string_view kind) : kind_(kind) {}

ResultKey& ResultKey::add(std::string_view name, double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", value);
  text_ += std::string(name) + "=" + text + "\n";
  return *this;
}

ResultKey& ResultKey::add(std::string_view name, std::string_view value) {
  text_ += std::string(name) + "=" + std::to_string(value.size()) + ":" + std::string(value) + "\n";
  return *this;
}

ResultKey& ResultKey::add(std::string_view name, std::span<const double> values) {
  text_ += std::string(name) + "[" + std::to_string(values.size()) + "]=";
  for (double v : values) {
    char text[40];
    std::snprintf(text, sizeof text, "%a,", v);
    text_ += text;
  }
  text_ += "\n";
  return *this;
}

ResultCache ResultCache::from_environment() {
  const fs::path dir = cache_dir_from_environment();
  return ResultCache(dir.empty() ? dir : dir / "results");
}

fs::path ResultCache::file(const ResultKey& key) const {
  return dir_.empty() ? fs::path() : dir_ / (std::string(key.kind()) + "-" + digest_of(key) + ".bin");
}

std::optional<std::vector<std::byte>> ResultCache::load(const ResultKey& key) const {
  if (dir_.empty()) return std::nullopt;
  const fs::path path = file(key);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  Result<std::vector<std::byte>> data = read_file_bytes(path);
  if (!data || data->size() < kResultHeader) return std::nullopt;
  const std::string_view text(reinterpret_cast<const char*>(data->data()), kResultHeader);
  const std::span<const std::byte> payload = std::span(*data).subspan(kResultHeader);
  if (text.substr(0, kResultMagic.size()) != kResultMagic ||
      text.substr(kResultMagic.size(), 65) != digest_of(key) + "\n" ||
      text.substr(kResultMagic.size() + 65, 65) != sha256_hex(payload) + "\n")
    return std::nullopt;
  fs::last_write_time(path, fs::file_time_type::clock::now(), ec);  // recently used: evicted last
  return std::vector<std::byte>(payload.begin(), payload.end());
}

void ResultCache::store(const ResultKey& key, std::span<const std::byte> bytes, size_t max_kept) const {
  if (dir_.empty() || max_kept == 0) return;
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) return;
  evict_oldest(dir_, key.kind(), max_kept);
  const std::string header = std::string(kResultMagic) + digest_of(key) + "\n" + sha256_hex(bytes) + "\n";
  std::vector<std::byte> file_bytes(header.size() + bytes.size());
  std::memcpy(file_bytes.data(), header.data(), header.size());
  if (!bytes.empty()) std::memcpy(file_bytes.data() + header.size(), bytes.data(), bytes.size());
  (void)write_file_atomic(file(key), file_bytes);
}

}  // namespace lagoon::io
