#include "io/json_limits.h"

#include <algorithm>
#include <vector>

namespace lagoon::io {
namespace {

struct Container {
  bool is_array = false;
  bool has_element = false;
  size_t elements = 0;
};

std::string where(size_t line, size_t column) {
  return " at line " + std::to_string(line) + ", column " + std::to_string(column);
}

}  // namespace

std::optional<std::string> json_limit_exceeded(std::string_view text, const JsonLimits& limits) {
  std::vector<Container> open;  // at most max_depth entries: deeper input is refused on the spot
  open.reserve(size_t(std::max(limits.max_depth, 0)));
  bool in_string = false, escaped = false;
  size_t string_bytes = 0, line = 1, column = 0;
  for (const char c : text) {
    ++column;
    if (c == '\n') line += 1, column = 0;
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
        continue;  // the closing quote is not part of the string
      }
      if (++string_bytes > limits.max_string_bytes)
        return "a string longer than " + std::to_string(limits.max_string_bytes) + " bytes" +
               where(line, column);
      continue;
    }
    const bool space = c == ' ' || c == '\t' || c == '\n' || c == '\r';
    if (space) continue;
    // Any token directly inside an array other than its closing bracket or a comma belongs to an element.
    if (!open.empty() && open.back().is_array && c != ']' && c != ',' && !open.back().has_element) {
      open.back().has_element = true;
      if (++open.back().elements > limits.max_array_length)
        return "an array of more than " + std::to_string(limits.max_array_length) + " elements" +
               where(line, column);
    }
    if (c == '"') {
      in_string = true;
      string_bytes = 0;
    } else if (c == '[' || c == '{') {
      if (int(open.size()) >= limits.max_depth)
        return "arrays or objects nested more than " + std::to_string(limits.max_depth) + " deep" +
               where(line, column);
      open.push_back({c == '[', false, 0});
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();
    } else if (c == ',' && !open.empty()) {
      open.back().has_element = false;
    }
  }
  return std::nullopt;
}

}  // namespace lagoon::io
