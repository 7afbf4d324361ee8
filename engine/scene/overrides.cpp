#include "scene/overrides.h"

#include "scene/json_fields.h"

namespace lagoon::scene {
namespace {

constexpr std::string_view kForm = "expected the form --set path=value, e.g. --set camera.fov_deg=40";

std::string_view trim(std::string_view s) {
  const size_t begin = s.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

Error assignment_error(std::string_view assignment, std::string_view problem) {
  return Error{"--set " + std::string(assignment) + ": " + std::string(problem) + "; " + std::string(kForm)};
}

// For "camera.fov_deg.x=1": camera.fov_deg holds a number, so there is no field "x" to set.
Error not_an_object(std::string_view assignment, const std::string& path, const nlohmann::json& node,
                    const std::string& key) {
  const std::string fix =
      path.empty() ? "a scene document must be a JSON object"
                   : "set " + path + " as a whole, e.g. --set " + path + "=" +
                         node.dump(-1, ' ', /*ensure_ascii=*/true, nlohmann::json::error_handler_t::replace);
  return Error{"--set " + std::string(assignment) + ": " + (path.empty() ? "the top level" : path) + " is " +
               describe_value(node) + ", not an object, so it has no field '" + key + "'; " + fix};
}

// "cascades[2]" -> ("cascades", 2); anything else -> (key, npos).
std::pair<std::string, size_t> split_index(const std::string& key) {
  const size_t open = key.find('[');
  if (open == std::string::npos || open == 0 || key.back() != ']') return {key, std::string::npos};
  const std::string digits = key.substr(open + 1, key.size() - open - 2);
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6)
    return {key, std::string::npos};
  return {key.substr(0, open), std::stoul(digits)};
}

}  // namespace

Result<Assignment> parse_assignment(std::string_view assignment) {
  const size_t eq = assignment.find('=');
  if (eq == std::string_view::npos) return assignment_error(assignment, "missing '='");
  Assignment result;
  result.path = std::string(trim(assignment.substr(0, eq)));
  if (result.path.empty()) return assignment_error(assignment, "empty field path before '='");
  for (size_t start = 0;;) {
    const size_t dot = result.path.find('.', start);
    std::string key = result.path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (key.empty()) return assignment_error(assignment, "empty field name in path '" + result.path + "'");
    result.keys.push_back(std::move(key));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  // Not JSON (e.g. --set name=reef) means a bare string, which saves shell-quoting "\"reef\"".
  const std::string_view text = assignment.substr(eq + 1);
  if (const auto exceeded = io::json_limit_exceeded(text, kSceneJsonLimits))
    return assignment_error(assignment.substr(0, std::min<size_t>(eq + 1 + 40, assignment.size())),
                            "the value has " + *exceeded);
  result.value = nlohmann::json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (result.value.is_discarded()) result.value = std::string(text);
  return result;
}

Result<void> apply_override(nlohmann::json& document, std::string_view assignment) {
  try {
    Result<Assignment> parsed = parse_assignment(assignment);
    if (!parsed) return parsed.error();
    if (document.is_null()) document = nlohmann::json::object();
    nlohmann::json* node = &document;
    std::string path;  // of *node
    for (size_t i = 0; i < parsed->keys.size(); ++i) {
      const std::string& key = parsed->keys[i];
      if (!node->is_object()) return not_an_object(assignment, path, *node, key);
      // An element of an array the document has: "ocean.cascades[1].resolution=128". When the document has
      // no such array the literal key is set and validation explains how to give the whole array instead.
      if (const auto [name, index] = split_index(key);
          index != std::string::npos && node->contains(name) && (*node)[name].is_array()) {
        nlohmann::json& array = (*node)[name];
        const std::string array_path = path.empty() ? name : path + "." + name;
        if (index >= array.size())
          return Error{"--set " + std::string(assignment) + ": " + array_path + " has " +
                       std::to_string(array.size()) + " element(s), so [" + std::to_string(index) +
                       "] does not exist; indices start at 0, or set the whole array"};
        path = array_path + "[" + std::to_string(index) + "]";
        if (i + 1 == parsed->keys.size()) {
          array[index] = std::move(parsed->value);
          break;
        }
        node = &array[index];
        continue;
      }
      path = path.empty() ? key : path + "." + key;
      if (i + 1 == parsed->keys.size()) {
        (*node)[key] = std::move(parsed->value);
        break;
      }
      // Creating missing blocks lets --set render.width=64 work on a file without a render block.
      if (!node->contains(key)) (*node)[key] = nlohmann::json::object();
      node = &(*node)[key];
    }
    return {};
  } catch (const std::exception& e) {  // defensive: nlohmann only throws on misuse
    return Error{"--set " + std::string(assignment) + ": internal error: " + e.what()};
  }
}

}  // namespace lagoon::scene
