// JSON text into a document, with what plain parsing lets through reported: duplicate keys, text beyond
// kSceneJsonLimits. Declared in scene/json_fields.h.
#include <set>
#include <string>
#include <vector>

#include "core/bounded_file.h"
#include "io/json_limits.h"
#include "scene/json_fields.h"

namespace lagoon::scene {
namespace {

using nlohmann::json;

// Reports a key given twice in one object, at its JSON path. nlohmann's parser callback sees keys but not
// paths, so this tracks the path of the container being parsed.
class DuplicateKeys {
 public:
  explicit DuplicateKeys(Diagnostics& diag) : diag_(diag) {}

  // The parser callback; keeps every value (returns true).
  bool on_event(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        stack_.push_back(Frame{event == json::parse_event_t::object_start, value_path(), {}, {}, 0});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!stack_.empty()) stack_.pop_back();
        element_done();
        break;
      case json::parse_event_t::key:
        if (!stack_.empty()) record_key(parsed.get<std::string>());
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool is_object;
    std::string path;
    std::set<std::string> keys;
    std::string key;
    size_t index = 0;
  };

  std::string value_path() const {
    if (stack_.empty()) return std::string();
    const Frame& f = stack_.back();
    if (!f.is_object) return f.path + "[" + std::to_string(f.index) + "]";
    return f.path.empty() ? f.key : f.path + "." + f.key;
  }
  void element_done() {
    if (!stack_.empty() && !stack_.back().is_object) ++stack_.back().index;
  }
  void record_key(std::string key) {
    stack_.back().key = std::move(key);
    if (!stack_.back().keys.insert(stack_.back().key).second) {
      diag_.error(value_path(), "field appears more than once in the same object",
                  "keep only one (JSON parsers would silently use the last one)");
    }
  }

  Diagnostics& diag_;
  std::vector<Frame> stack_;
};

// what() is "[json.exception.parse_error.101] parse error at line L, column C: ..."; keep from "parse".
std::string without_exception_id(const json::exception& e) {
  std::string what = e.what();
  const size_t start = what.find("] ");
  if (start != std::string::npos) what = what.substr(start + 2);
  return what;
}

}  // namespace

std::optional<json> parse_json_text(std::string_view text, Diagnostics& diag) {
  if (const auto exceeded = io::json_limit_exceeded(text, kSceneJsonLimits)) {
    diag.file_error("JSON: " + *exceeded,
                    "a scene is a few nested objects with short strings and small arrays "
                    "(docs/scene-format.md); check that this is the scene file you meant");
    return std::nullopt;
  }
  DuplicateKeys duplicates(diag);
  const json::parser_callback_t callback = [&duplicates](int, json::parse_event_t event, json& parsed) {
    return duplicates.on_event(event, parsed);
  };
  try {
    json document = json::parse(text.begin(), text.end(), callback, /*allow_exceptions=*/true,
                                /*ignore_comments=*/false);
    if (!diag.ok()) return std::nullopt;
    return document;
  } catch (const json::parse_error& e) {
    diag.file_error("invalid JSON: " + without_exception_id(e),
                    "fix the syntax at that position (JSON allows no comments or trailing commas; use a "
                    "\"comment\" field for notes)");
  } catch (const json::exception& e) {  // e.g. out_of_range.406 "number overflow parsing '1e999'"
    diag.file_error("invalid JSON: " + without_exception_id(e), "write numbers that fit in a double");
  }
  return std::nullopt;
}

std::optional<std::string> read_json_file(const std::filesystem::path& path, Diagnostics& diag,
                                          const JsonFileKind& kind) {
  const std::string name(kind.name), example(kind.example);
  // Scene and path files are a few kilobytes; a huge one is the wrong file, and reading it whole would cost
  // its size. Checked before anything is read (core/bounded_file.h): /dev/zero or a FIFO is refused, not
  // read for ever.
  constexpr std::uintmax_t kMaxSceneBytes = std::uintmax_t{16} << 20;
  const FileCheck check = check_file_to_read(path, kMaxSceneBytes);
  switch (check.problem) {
    case FileProblem::kNone:
      break;
    case FileProblem::kMissing: {
      std::error_code ec;
      const std::filesystem::path cwd = std::filesystem::current_path(ec);
      diag.file_error("file not found", "check the path (relative paths start from the working directory " +
                                            cwd.string() + "); " + example + " is a starting point");
      return std::nullopt;
    }
    case FileProblem::kFolder:
      diag.file_error("is a directory, not a " + name, "pass a .json file such as " + example);
      return std::nullopt;
    case FileProblem::kNotRegular:
      diag.file_error(check.reason, "pass a " + name + " saved as a file, such as " + example);
      return std::nullopt;
    case FileProblem::kTooLarge:
      diag.file_error("is " + std::to_string(check.size >> 20) + " MiB; " + name + "s are limited to 16 MiB",
                      "check that this is the " + name + " you meant (" + example + " is " +
                          std::string(kind.example_size) + ")");
      return std::nullopt;
    case FileProblem::kUnreadable:
      diag.file_error(check.reason, "check that the file is readable by this user");
      return std::nullopt;
  }
  Result<std::string> text = read_checked_file(path, check);
  if (!text) {
    diag.file_error(text.error().message, "check that the file is readable by this user and its disk");
    return std::nullopt;
  }
  return std::move(*text);
}

}  // namespace lagoon::scene
