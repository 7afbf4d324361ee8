// NumPy .npy arrays of float32, for dumping spectra, height fields and readbacks that Python tools load
// with numpy.load(). Format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
#pragma once
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/result.h"

namespace lagoon::io {

class AtomicFile;

// Magic, version 1.0 and the header dict for a '<f4' C-order array of `shape`, padded so the data starts at
// a multiple of 64 bytes. Its size plus 4 bytes per element is the whole file's size.
Result<std::string> npy_header(std::span<const size_t> shape);

// Appends float32 values to an open file, little-endian whatever the host.
Result<void> write_npy_values(AtomicFile& file, std::span<const float> data);

// Writes a version 1.0 file, dtype '<f4', C order (last index fastest). Atomic (see AtomicFile); creates
// missing parent folders. An empty shape is a 0-d array holding exactly one value.
Result<void> write_npy(const std::filesystem::path& path, std::span<const float> data,
                       std::span<const size_t> shape);

struct NpyArray {
  std::vector<size_t> shape;
  std::vector<float> data;  // C order
};

// Accepts versions 1.0, 2.0 and 3.0 holding little-endian float32 in C order; anything else (other dtype,
// fortran_order, truncated data) is an error naming the path and the problem.
Result<NpyArray> read_npy(const std::filesystem::path& path);

}  // namespace lagoon::io
