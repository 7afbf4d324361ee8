// Results of costly, deterministic CPU work kept between runs in Lagoon's cache folder (core/cache_dir.h), so
// the next run of a scene skips them: the water LUTs, the PBR tables, the environment map (docs/building.md).
// A result is filed under the SHA-256 of its key, a text naming everything it was computed from, the code's
// fingerprint included: a changed input or a rebuilt Lagoon never reads a stale result. A missing,
// unreadable, truncated or damaged file is a miss (its checksum is verified); a read-only folder or a full
// disk only means the work is done again next time. At most kMaxResultsPerKind files of a kind are kept (the
// least recently used go), or fewer where a kind's results are large.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace lagoon::io {

inline constexpr size_t kMaxResultsPerKind = 64;

// The key: every input, by name, in a fixed order. Numbers are written exactly (hex floats).
class ResultKey {
 public:
  explicit ResultKey(std::string_view kind);
  ResultKey& add(std::string_view name, double value);
  ResultKey& add(std::string_view name, std::string_view text);
  ResultKey& add(std::string_view name, std::span<const double> values);
  std::string_view kind() const { return kind_; }
  const std::string& text() const { return text_; }

 private:
  std::string kind_, text_;
};

// Plain values and arrays to bytes and back, for the results' own formats.
class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  template <typename T>
  void put_vector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(uint64_t(values.size()));
    append(values.data(), values.size() * sizeof(T));
  }
  const std::vector<std::byte>& bytes() const { return bytes_; }

 private:
  // Grown and copied into rather than insert()ed: GCC 12 inlines insert() of a few bytes into a false
  // -Wstringop-overflow where it also sees the vector's first allocation.
  void append(const void* data, size_t size) {
    const size_t at = bytes_.size();
    bytes_.resize(at + size);
    if (size > 0) std::memcpy(bytes_.data() + at, data, size);
  }
  std::vector<std::byte> bytes_;
};

// Reads what a ByteWriter wrote; ok() turns false (and stays) at the first read past the end.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::byte> bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value{};
    if (!take(&value, sizeof(T))) ok_ = false;
    return value;
  }
  template <typename T>
  std::vector<T> get_vector(size_t max_count) {
    const uint64_t n = get<uint64_t>();
    if (!ok_ || n > max_count || n * sizeof(T) > bytes_.size() - at_) {
      ok_ = false;
      return {};
    }
    std::vector<T> values(n);
    take(values.data(), n * sizeof(T));
    return values;
  }
  // True when every read was in bounds and the bytes are used up.
  bool complete() const { return ok_ && at_ == bytes_.size(); }

 private:
  bool take(void* out, size_t n) {
    if (!ok_ || n > bytes_.size() - at_) return false;
    std::memcpy(out, bytes_.data() + at_, n);
    at_ += n;
    return true;
  }
  std::span<const std::byte> bytes_;
  size_t at_ = 0;
  bool ok_ = true;
};

class ResultCache {
 public:
  // In `dir`; an empty dir caches nothing.
  explicit ResultCache(std::filesystem::path dir) : dir_(std::move(dir)) {}
  // The folder from the environment (LAGOON_PIPELINE_CACHE etc.) plus "results".
  static ResultCache from_environment();
  // False when it caches nothing (LAGOON_PIPELINE_CACHE=off): a result that is costly to read back for
  // storing need not be.
  bool enabled() const { return !dir_.empty(); }

  std::optional<std::vector<std::byte>> load(const ResultKey& key) const;
  // Best effort: a failure to write is not an error (the result was computed anyway). Keeps at most
  // `max_kept` results of the key's kind, the least recently used going first.
  void store(const ResultKey& key, std::span<const std::byte> bytes,
             size_t max_kept = kMaxResultsPerKind) const;
  std::filesystem::path file(const ResultKey& key) const;

  // The commonest result: one array of exactly `count` plain values (a table, a texture's texels). A file
  // holding another count, or anything more, is a miss.
  template <typename T>
  std::optional<std::vector<T>> load_vector(const ResultKey& key, size_t count) const {
    auto bytes = load(key);
    if (!bytes) return std::nullopt;
    ByteReader in(*bytes);
    std::vector<T> values = in.get_vector<T>(count);
    if (!in.complete() || values.size() != count) return std::nullopt;
    return values;
  }
  template <typename T>
  void store_vector(const ResultKey& key, const std::vector<T>& values,
                    size_t max_kept = kMaxResultsPerKind) const {
    ByteWriter out;
    out.put_vector(values);
    store(key, out.bytes(), max_kept);
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace lagoon::io
