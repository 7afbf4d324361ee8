// Free space where an output will go, to refuse a long write up front rather than fail half-way.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/result.h"

namespace lagoon::io {

// Bytes available to this user on the file system that will hold `path` (which need not exist yet: its
// nearest existing ancestor is asked).
Result<uint64_t> available_bytes(const std::filesystem::path& path);

// "1.5 GiB", "320 MiB", "12 KiB", "100 B": sizes in messages.
std::string format_bytes(uint64_t bytes);

}  // namespace lagoon::io
