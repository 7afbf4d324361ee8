// SHA-256 (FIPS 180-4) of bytes and of files, as lowercase hex: the checksums of a dataset's manifest
// (docs/datasets.md), the same digest `sha256sum` prints, so a set can be checked without Lagoon too.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "core/result.h"

namespace lagoon::io {

class Sha256 {
 public:
  Sha256();
  void update(std::span<const std::byte> bytes);
  // The digest as 64 lowercase hex digits. The object is spent afterwards.
  std::string hex();

 private:
  void block(const uint8_t* p);
  std::array<uint32_t, 8> h_;
  std::array<uint8_t, 64> buffer_{};
  size_t buffered_ = 0;
  uint64_t length_ = 0;  // bytes
};

std::string sha256_hex(std::span<const std::byte> bytes);
// Reads the file in pieces (constant memory); the error names the path and the OS reason.
Result<std::string> sha256_file(const std::filesystem::path& path);

}  // namespace lagoon::io
