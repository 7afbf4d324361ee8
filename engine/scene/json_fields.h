// Strict, declarative reading of JSON objects into C++ structs.
//
// A block is described by one function `void read_x(ObjectReader& r, X& x)` that declares each field once
// (name, type, range, unit, doc line; the default is the struct member's initial value). The same function
// validates a document (read mode) and lists the fields for the docs (describe mode), so the parser and
// docs/scene-format.md cannot drift apart. Problems are collected, not thrown, so one run reports them all.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include "io/json_limits.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/result.h"

namespace lagoon::scene {

// Allowed values of a numeric field; validates and renders itself for messages and docs.
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // true: value must be strictly greater than min
  bool max_open = false;

  static Bounds any() { return Bounds(); }
  static Bounds between(double lo, double hi);      // lo <= v <= hi
  static Bounds above(double lo);                   // v > lo
  static Bounds at_least(double lo);                // v >= lo
  static Bounds above_up_to(double lo, double hi);  // lo < v <= hi
  bool contains(double v) const;
  Bounds as_float() const;       // the ends rounded to float, for a value stored as float
  std::string describe() const;  // "1 to 170", "> 0", "any"
};

// One row of the field reference.
struct FieldInfo {
  std::string path;  // "camera.fov_deg"
  std::string type;  // "number", "integer", "[x, y, z]", "boolean", "string", "object", "array of objects"
  std::string unit;
  std::string default_value;
  std::string range;
  std::string doc;
  // For editors (the demo's panel): numeric limits (numbers, integers, each element of a vector), the
  // allowed values of a choice or a power-of-two size, and the element count limits of an array.
  Bounds bounds;
  std::vector<std::string> choices;
  size_t min_elements = 0, max_elements = 0;
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
  void number(std::string_view name, double& value, Bounds bounds, std::string_view unit,
              std::string_view doc);
  void integer(std::string_view name, uint32_t& value, Bounds bounds, std::string_view unit,
               std::string_view doc);
  // Power of two in [min, max], e.g. an FFT or texture size.
  void power_of_two(std::string_view name, uint32_t& value, uint32_t min, uint32_t max, std::string_view unit,
                    std::string_view doc);
  // Optional number: no default; absent leaves `value` empty (e.g. the camera's yaw_deg, an alternative to
  // look_at, where a default would hide which of the two the file chose).
  void number(std::string_view name, std::optional<double>& value, Bounds bounds, std::string_view unit,
              std::string_view doc);
  void number(std::string_view name, std::optional<float>& value, Bounds bounds, std::string_view unit,
              std::string_view doc);
  void vec3(std::string_view name, glm::vec3& value, std::string_view unit, std::string_view doc);
  // Three numbers, each within `bounds`; `form` names them in the docs and messages: "[r, g, b]",
  // "[yaw, pitch, roll]".
  void vec3(std::string_view name, glm::vec3& value, std::string_view form, Bounds bounds,
            std::string_view unit, std::string_view doc);
  // A point on the horizontal plane, [x, z] (y is up): two finite numbers.
  void vec2(std::string_view name, glm::vec2& value, std::string_view unit, std::string_view doc);
  // A list of points on the horizontal plane, [[x, z], ...], with min_size to max_size points, each finite.
  void points2(std::string_view name, std::vector<glm::vec2>& value, size_t min_size, size_t max_size,
               std::string_view unit, std::string_view doc);
  void flag(std::string_view name, bool& value, std::string_view doc);
  void text(std::string_view name, std::string& value, std::string_view doc);

  // A string that must be one of `options` (name, value); stored as the value. Unknown names get a
  // did-you-mean and the list of allowed names.
  template <typename E>
  void choice(std::string_view name, E& value, const std::vector<std::pair<std::string, E>>& options,
              std::string_view doc) {
    std::vector<std::string> names;
    size_t current = options.size();  // value not among the options: the docs show no default
    for (size_t i = 0; i < options.size(); ++i) {
      names.push_back(options[i].first);
      if (options[i].second == value) current = i;
    }
    if (const std::optional<size_t> picked = choose(name, names, current, doc))
      value = options[*picked].second;
  }

  // Nested object read by `read(ObjectReader&, T&)`; absent means "all defaults".
  template <typename T, typename ReadFn>
  void block(std::string_view name, T& value, ReadFn&& read, std::string_view doc) {
    std::optional<ObjectReader> child = open_block(name, doc);
    if (!child) return;
    read(*child, value);
    child->finish();
  }

  // Array of objects, each element read by `read(ObjectReader&, T&)` starting from a default T. Absent
  // keeps `values` (the defaults); present replaces them entirely, so a file states the whole list rather
  // than patching the defaults element by element. Element paths are "name[1]"; the docs list the element
  // fields once, as "name[].field".
  template <typename T, typename ReadFn>
  void array(std::string_view name, std::vector<T>& values, size_t min_size, size_t max_size, ReadFn&& read,
             std::string_view doc) {
    // The defaults, rendered as JSON for the docs and for messages, come from the same read function.
    std::vector<std::vector<FieldInfo>> defaults;
    for (T element : values) {  // a copy: read() takes T& even though describing never writes
      ObjectReader describer("", defaults.emplace_back());
      read(describer, element);
    }
    if (describing()) {
      ObjectReader element_reader = describe_array(name, defaults, min_size, max_size, doc);
      T element{};
      read(element_reader, element);
      return;
    }
    std::optional<std::vector<std::optional<ObjectReader>>> elements =
        open_array(name, defaults, min_size, max_size);
    if (!elements) return;
    std::vector<T> result;
    bool all_objects = true;
    for (std::optional<ObjectReader>& element : *elements) {
      if (!element) {
        all_objects = false;
        continue;
      }
      read(*element, result.emplace_back());
      element->finish();
    }
    // A wrong length is already reported; keeping the elements still lets cross-element rules check them.
    if (all_objects) values = std::move(result);
  }

  // Cross-field rule such as far_m > near_m, stated once for the error and the docs' range column
  // ("must be <rule>"). `fix` should quote the offending values. A rule on an array element field
  // ("cascades[2].patch_size_m") is documented once, on the element row ("cascades[].patch_size_m").
  void rule(std::string_view name, bool holds, std::string_view rule, std::string_view fix);

  // Whether the object being read has the field (false when describing), for rules that depend on which
  // fields a file states, not on their values: a default look_at cannot be told apart from a given one.
  bool has(std::string_view name) const;

  // Reports fields nobody declared (with a did-you-mean) and a non-string "comment".
  void finish();

 private:
  bool describing() const { return catalog_ != nullptr; }
  std::string child_path(std::string_view name) const;
  const nlohmann::json* lookup(std::string_view name);  // declares `name`; null if absent or describing
  void describe(std::string_view name, std::string type, std::string_view unit, std::string default_value,
                std::string range, std::string_view doc, Bounds bounds = {});
  std::optional<ObjectReader> open_block(std::string_view name, std::string_view doc);
  std::optional<size_t> choose(std::string_view name, const std::vector<std::string>& names, size_t current,
                               std::string_view doc);
  ObjectReader describe_array(std::string_view name, const std::vector<std::vector<FieldInfo>>& defaults,
                              size_t min_size, size_t max_size, std::string_view doc);
  // Null after reporting a non-array; otherwise one reader per element, null for non-object elements.
  std::optional<std::vector<std::optional<ObjectReader>>> open_array(
      std::string_view name, const std::vector<std::vector<FieldInfo>>& defaults, size_t min_size,
      size_t max_size);
  // Shared by the number() overloads; `as_float` also checks the value after rounding to float.
  // `default_text` is "" for a field without a default.
  std::optional<double> read_number(std::string_view name, const std::string& default_text, Bounds bounds,
                                    std::string_view unit, bool as_float);
  // Shared by vec2() and vec3(): reads `values.size()` numbers written as `form` over the defaults in
  // `values`; false (and `values` partly overwritten) unless all were read.
  bool read_floats(std::string_view name, std::span<float> values, std::string_view form, Bounds bounds,
                   std::string_view unit, std::string_view doc);

  const nlohmann::json* object_ = nullptr;
  Diagnostics* diag_ = nullptr;
  std::vector<FieldInfo>* catalog_ = nullptr;
  std::string path_;
  std::vector<std::string> declared_;
  std::map<std::string, std::string, std::less<>> array_defaults_;  // name -> JSON, for finish()'s hints
};

// What scene JSON may hold (a scene nests about five deep; the longest strings are file paths): text beyond
// these is refused before parsing, so hostile input cannot exhaust the stack or memory.
inline constexpr io::JsonLimits kSceneJsonLimits{
    .max_depth = 32, .max_array_length = 4096, .max_string_bytes = 4096};

// What a JSON file holds, for messages: "scene file", "scenes/default.json", "about 2 KB".
struct JsonFileKind {
  std::string_view name, example, example_size;
};
// Reads a JSON file whole (at most 16 MiB), reporting a missing file, a folder, a huge file or a read error
// as a file error that points at a shipped example of the kind.
std::optional<std::string> read_json_file(const std::filesystem::path& path, Diagnostics& diag,
                                          const JsonFileKind& kind);

// Parses JSON text, reporting syntax errors with nlohmann's line/column and duplicate keys (which plain
// JSON parsing would silently resolve to the last one), and text beyond kSceneJsonLimits. Never throws.
std::optional<nlohmann::json> parse_json_text(std::string_view text, Diagnostics& diag);

// The JSON object whose fields have the values describe mode recorded (FieldInfo::default_value): with a
// describer run over a live object, that object's JSON.
nlohmann::ordered_json fields_to_json(const std::vector<FieldInfo>& fields);

// The field reference as a Markdown table (embedded in docs/scene-format.md, checked by a test).
std::string to_markdown_table(const std::vector<FieldInfo>& fields);

// Short, always-valid rendering of a JSON value for messages: `200`, `string "wide"`, `array [1,2]`.
std::string describe_value(const nlohmann::json& value);

// Numbers for messages and docs, to 6 significant digits: 0.1f -> "0.1", 5000 -> "5000"; whole numbers
// exactly, so 4294967295 does not print as 4.29497e+09.
std::string format_number(double v);

// Closest candidate by edit distance if it is plausibly a typo of `name`, else "".
std::string closest_match(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace lagoon::scene
