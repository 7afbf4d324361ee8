// A whole number written out in full ("42", "-7"): nullopt for anything else (empty, a sign alone, trailing
// characters, out of range). Shared by the command-line options and the dataset's --shard I/N.
#pragma once
#include <charconv>
#include <optional>
#include <string_view>

namespace lagoon {

inline std::optional<long long> parse_whole_number(std::string_view text) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

}  // namespace lagoon
