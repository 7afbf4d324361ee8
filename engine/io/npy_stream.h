// A float32 .npy array written one slab (one index of the first axis) at a time, so that a long run of
// frames goes to disk as it is computed and memory holds one frame, whatever the length. The header is
// written first for the final shape; the file appears at its path only when commit() finds every slab in
// (AtomicFile), so an error or an interruption half-way leaves no truncated array behind.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "core/result.h"
#include "io/atomic_file.h"

namespace lagoon::io {

class NpyStreamWriter {
 public:
  // `shape` has at least one axis; shape[0] slabs of product(shape[1..]) values each will follow.
  static Result<NpyStreamWriter> create(const std::filesystem::path& path, std::span<const size_t> shape);

  // Exactly slab_size() values; more slabs than shape[0] is an error.
  Result<void> append(std::span<const float> slab);
  // Fails, and writes nothing, unless all shape[0] slabs were appended.
  Result<void> commit();

  size_t slab_size() const { return slab_size_; }
  size_t slabs_written() const { return written_; }

 private:
  NpyStreamWriter(AtomicFile file, std::vector<size_t> shape, size_t slab_size)
      : file_(std::move(file)), shape_(std::move(shape)), slab_size_(slab_size) {}

  AtomicFile file_;
  std::vector<size_t> shape_;
  size_t slab_size_ = 0;
  size_t written_ = 0;
};

// Bytes of a .npy file of float32 `shape` (header included): what an export will need on disk.
Result<uint64_t> npy_file_bytes(std::span<const size_t> shape);

}  // namespace lagoon::io
