// A rendered set's manifest (docs/datasets.md): one JSON-lines file per shard, OUT.shard-I-of-N.jsonl, whose
// first line says what run produced it and whose every further line lists one finished frame's files with
// their SHA-256. A line is appended (and synced) only after all of its frame's files are complete, so a shard
// killed at any moment resumes by skipping the frames its manifest lists and whose files still match; a line
// cut off by the kill is dropped. verify_dataset() checks a finished set against its manifests.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/result.h"

namespace lagoon::dataset {

struct ManifestFile {
  std::string name;  // relative to the manifest's folder
  std::string sha256;
  uintmax_t bytes = 0;
};

struct ManifestFrame {
  long long frame = 0;
  double time_s = 0;
  std::string device;  // the Vulkan device that rendered it
  std::vector<ManifestFile> files;
};

struct Manifest {
  nlohmann::json run;  // what produced the set (scene and its checksum, options); equal for every shard
  long long frames = 0;
  long long shard_index = 0, shard_count = 1;
  std::vector<ManifestFrame> entries;
  bool cut_off_tail = false;  // the last line was incomplete (killed while appending) and is left out
};

// The error names the file, the line and what is wrong with it.
Result<Manifest> read_manifest(const std::filesystem::path& path);

// Hashes `path` and describes it as `name` for a manifest entry.
Result<ManifestFile> describe_file(const std::filesystem::path& path, const std::string& name);

class ManifestWriter {
 public:
  // Writes `manifest` (its header and entries) to `path` atomically, then keeps the file open for appending.
  static Result<ManifestWriter> create(const std::filesystem::path& path, const Manifest& manifest);
  ManifestWriter(ManifestWriter&& other) noexcept;
  ManifestWriter& operator=(ManifestWriter&&) = delete;
  ~ManifestWriter();
  // One line, written and fsynced before it returns.
  Result<void> append(const ManifestFrame& frame);

 private:
  ManifestWriter(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
  std::filesystem::path path_;
  int fd_ = -1;
};

// Whether every file an entry lists still has its size and checksum ("" if so, else why not).
std::string entry_mismatch(const std::filesystem::path& folder, const ManifestFrame& frame);

struct DatasetReport {
  long long sets = 0, frames = 0, files = 0;
  uintmax_t bytes = 0;
  std::vector<std::string> problems;  // one line each, naming the file or frame and what to do
};
// Every OUT.shard-I-of-N.jsonl in `folder`, grouped by OUT: all N shards present with the same run, every
// frame from 0 to frames - 1 listed exactly once, every file present with its size and checksum.
DatasetReport verify_dataset(const std::filesystem::path& folder);

}  // namespace lagoon::dataset
