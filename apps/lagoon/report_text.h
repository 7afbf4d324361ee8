// Text the commands' reports share: numbers in tables and writing a report file with a message on failure.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace lagoon::cli {

// `v` with `digits` decimals ("%.*f").
std::string fixed(double v, int digits = 1);

// Writes `text` to `path` atomically (no half-written file). On failure prints "<command>: <why>" to stderr
// and returns false.
bool write_report_text(const std::filesystem::path& path, std::string_view text, const char* command);

}  // namespace lagoon::cli
