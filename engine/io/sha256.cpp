#include "io/sha256.h"

#include <nettle/sha2.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/bounded_file.h"
#include "io/atomic_file.h"

namespace lagoon::io {

// nettle's context, kept out of the header so hosts including sha256.h need no nettle headers.
struct Sha256::State {
  sha256_ctx ctx;
};

Sha256::Sha256() : state_(std::make_unique<State>()) {
  sha256_init(&state_->ctx);
}
Sha256::~Sha256() = default;
Sha256::Sha256(Sha256&&) noexcept = default;
Sha256& Sha256::operator=(Sha256&&) noexcept = default;

void Sha256::update(std::span<const std::byte> bytes) {
  sha256_update(&state_->ctx, bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()));
}

std::string Sha256::hex() {
  std::array<uint8_t, SHA256_DIGEST_SIZE> digest;
  sha256_digest(&state_->ctx, digest.size(), digest.data());
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (uint8_t b : digest) {
    out += kHex[b >> 4];
    out += kHex[b & 15];
  }
  return out;
}

std::string sha256_hex(std::span<const std::byte> bytes) {
  Sha256 sha;
  sha.update(bytes);
  return sha.hex();
}

Result<std::string> sha256_file(const std::filesystem::path& path) {
  // Streamed, so any size is fine; but only a regular file, which ends (core/bounded_file.h).
  if (const FileCheck check = check_file_to_read(path, UINTMAX_MAX); !check)
    return Error{"cannot hash " + path.string() + ": it " + check.reason};
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) return Error{os_error_message("cannot open", path, errno)};
  Sha256 sha;
  std::vector<std::byte> chunk(1 << 16);
  while (size_t n = std::fread(chunk.data(), 1, chunk.size(), file.get())) sha.update({chunk.data(), n});
  if (std::ferror(file.get())) return Error{os_error_message("cannot read", path, errno)};
  return sha.hex();
}

}  // namespace lagoon::io
