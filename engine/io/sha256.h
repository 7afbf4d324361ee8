// SHA-256 (FIPS 180-4) of bytes and of files, as lowercase hex: the checksums of a dataset's manifest
// (docs/datasets.md), the same digest `sha256sum` prints, so a set can be checked without Lagoon too.
// Computed by nettle (Debian's nettle-dev), a maintained library, not by code of Lagoon's own.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "core/result.h"

namespace lagoon::io {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(Sha256&&) noexcept;
  Sha256& operator=(Sha256&&) noexcept;
  void update(std::span<const std::byte> bytes);
  // The digest as 64 lowercase hex digits; the object starts a new digest afterwards.
  std::string hex();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

std::string sha256_hex(std::span<const std::byte> bytes);
// Reads the file in pieces (constant memory); the error names the path and the OS reason.
Result<std::string> sha256_file(const std::filesystem::path& path);

}  // namespace lagoon::io
