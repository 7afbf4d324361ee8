// Strict, declarative reading of JSON objects into C++ structs.
//
// A block is described by one function `void read_x(ObjectReader& r, X& x)` that declares each field once
// (name, type, range, unit, doc line; the default is the struct member's initial value). The same function
// validates a document (read mode) and lists the fields for the docs (describe mode), so the parser and
// docs/scene-format.md cannot drift apart. Problems are collected, not thrown, so one run reports them all.
#pragma once
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "vk/result.h"

namespace lagoon::scene {

// Allowed values of a numeric field; validates and renders itself for messages and docs.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // true: value must be strictly greater than min
  bool max_open = false;

  static Bounds any() { return Bounds(); }
  static Bounds between(double lo, double hi);  // lo <= v <= hi
  static Bounds above(double lo);               // v > lo
  static Bounds at_least(double lo);            // v >= lo
  bool contains(double v) const;
  std::string describe() const;  // "1 to 170", "> 0", "any"
};

// One row of the field reference.
struct FieldInfo {
  std::string path;  // "camera.fov_deg"
  std::string type;  // "number", "integer", "[x, y, z]", "boolean", "string", "object"
  std::string unit;
  std::string default_value;
  std::string range;
  std::string doc;
};

// Collects problems as "<source>: <json path>: <what is wrong>; <how to fix it>" lines.
class Diagnostics {
 public:
  explicit Diagnostics(std::string source) : source_(std::move(source)) {}
  void error(std::string_view path, std::string_view problem, std::string_view fix);
  void file_error(std::string_view problem, std::string_view fix);  // not tied to a field
  // Errors at or below `path` get "(value from --set <assignment>)" so users know where to look.
  void note_override(std::string path, std::string assignment);
  bool ok() const { return lines_.empty(); }
  Error to_error() const;  // all problems, one per line

 private:
  std::string source_;
  std::vector<std::string> lines_;
  std::vector<std::pair<std::string, std::string>> overrides_;  // (path, assignment)
};

class ObjectReader {
 public:
  // Read mode: validates `object` (whose JSON path is `path`, "" for the document root).
  ObjectReader(const nlohmann::json& object, std::string path, Diagnostics& diag);
  // Describe mode: appends one FieldInfo per declared field to `catalog`; values are left untouched.
  ObjectReader(std::string path, std::vector<FieldInfo>& catalog);

  void number(std::string_view name, float& value, Bounds bounds, std::string_view unit,
              std::string_view doc);
  void integer(std::string_view name, uint32_t& value, Bounds bounds, std::string_view unit,
               std::string_view doc);
  void vec3(std::string_view name, glm::vec3& value, std::string_view unit, std::string_view doc);
  void flag(std::string_view name, bool& value, std::string_view doc);
  void text(std::string_view name, std::string& value, std::string_view doc);

  // Nested object read by `read(ObjectReader&, T&)`; absent means "all defaults".
  template <typename T, typename ReadFn>
  void block(std::string_view name, T& value, ReadFn&& read, std::string_view doc) {
    std::optional<ObjectReader> child = open_block(name, doc);
    if (!child) return;
    read(*child, value);
    child->finish();
  }

  // Cross-field rule such as far_m > near_m, stated once for the error and the docs' range column
  // ("must be <rule>"). `fix` should quote the offending values.
  void rule(std::string_view name, bool holds, std::string_view rule, std::string_view fix);

  // Reports fields nobody declared (with a did-you-mean) and a non-string "comment".
  void finish();

 private:
  bool describing() const { return catalog_ != nullptr; }
  std::string child_path(std::string_view name) const;
  const nlohmann::json* lookup(std::string_view name);  // declares `name`; null if absent or describing
  void describe(std::string_view name, std::string type, std::string_view unit, std::string default_value,
                std::string range, std::string_view doc);
  std::optional<ObjectReader> open_block(std::string_view name, std::string_view doc);

  const nlohmann::json* object_ = nullptr;
  Diagnostics* diag_ = nullptr;
  std::vector<FieldInfo>* catalog_ = nullptr;
  std::string path_;
  std::vector<std::string> declared_;
};

// Parses JSON text, reporting syntax errors with nlohmann's line/column and duplicate keys (which plain
// JSON parsing would silently resolve to the last one). Never throws.
std::optional<nlohmann::json> parse_json_text(std::string_view text, Diagnostics& diag);

// The field reference as a Markdown table (embedded in docs/scene-format.md, checked by a test).
std::string to_markdown_table(const std::vector<FieldInfo>& fields);

// Short, always-valid rendering of a JSON value for messages: `200`, `string "wide"`, `array [1,2]`.
std::string describe_value(const nlohmann::json& value);

// Numbers for messages and docs, to 6 significant digits: 0.1f -> "0.1", 5000 -> "5000".
std::string format_number(double v);

// Closest candidate by edit distance if it is plausibly a typo of `name`, else "".
std::string closest_match(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace lagoon::scene
