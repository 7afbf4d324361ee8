// Bounds on JSON text checked before it is parsed. A parser holds a frame per nesting level and copies of
// every string, so hostile input (100,000 nested arrays, a string of a gigabyte) would overflow the stack or
// exhaust memory; a text scan finds that first, in one pass with constant memory.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace lagoon::io {

struct JsonLimits {
  int max_depth = 64;                 // arrays and objects nested inside each other
  size_t max_array_length = 1 << 16;  // elements of one array
  size_t max_string_bytes = 4096;     // of one string, as written (escapes count as written)
};

// The first limit `text` exceeds, as "<what> at line L, column C (the limit is N)", or nothing. The text need
// not be valid JSON: syntax errors are the parser's to report.
std::optional<std::string> json_limit_exceeded(std::string_view text, const JsonLimits& limits);

}  // namespace lagoon::io
