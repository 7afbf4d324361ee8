#include "scene/json_fields.h"

#include "io/json_limits.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

namespace lagoon::scene {
namespace {

using nlohmann::json;

constexpr double kFloatMax = std::numeric_limits<float>::max();

std::string format_floats(std::span<const float> values) {
  std::string out;
  for (float v : values) out += (out.empty() ? "[" : ", ") + format_number(v);
  return out + "]";
}

std::string with_unit(std::string text, std::string_view unit) {
  if (!unit.empty()) text += " " + std::string(unit);
  return text;
}

std::string join_path(std::string_view parent, std::string_view name) {
  return parent.empty() ? std::string(name) : std::string(parent) + "." + std::string(name);
}

std::string join_list(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

// Case-insensitive Levenshtein distance.
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitute = diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

// Returns the value as a double, or nullopt after reporting why it is not a usable number.
std::optional<double> finite_number(const json& j, const std::string& path, const std::string& fix,
                                    Diagnostics& diag) {
  if (!j.is_number()) {
    diag.error(path, "expected a number, got " + describe_value(j), fix);
    return std::nullopt;
  }
  const double v = j.get<double>();
  // Ranges and float conversion both need finite values; JSON cannot spell NaN but 1e999 and in-memory
  // documents can produce non-finite values.
  if (!std::isfinite(v) || std::abs(v) > kFloatMax) {
    diag.error(path, describe_value(j) + " is not a finite 32-bit float", fix);
    return std::nullopt;
  }
  return v;
}

// Returns the value if it is a whole number (64.0 counts), or nullopt after reporting why not.
std::optional<double> whole_number(const json& j, const std::string& path, const std::string& fix,
                                   Diagnostics& diag) {
  if (!j.is_number()) {
    diag.error(path, "expected an integer, got " + describe_value(j), fix);
    return std::nullopt;
  }
  const double v = j.get<double>();  // exact for every in-range value
  if (!std::isfinite(v) || std::floor(v) != v) {
    diag.error(path, describe_value(j) + " is not a whole number", fix);
    return std::nullopt;
  }
  return v;
}

// "cascades[2].patch_size_m" -> "cascades[].patch_size_m": the docs describe array elements once.
std::string strip_indices(std::string_view path) {
  std::string out;
  for (size_t i = 0; i < path.size(); ++i) {
    out += path[i];
    if (path[i] != '[') continue;
    while (i + 1 < path.size() && std::isdigit(static_cast<unsigned char>(path[i + 1]))) ++i;
  }
  return out;
}

// Rebuilds one array element's JSON from its describe-mode rows, so array defaults can be shown as JSON
// ({"patch_size_m":1000,"resolution":256}) without a second, hand-written serializer to keep in sync.
nlohmann::ordered_json element_json(const std::vector<FieldInfo>& fields) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  for (const FieldInfo& f : fields) {
    // Blocks have no default of their own (their fields follow); nested arrays carry theirs on their row.
    if (f.default_value.empty() || f.path.find('[') != std::string::npos) continue;
    nlohmann::ordered_json value = nlohmann::ordered_json::parse(f.default_value, nullptr, false);
    if (value.is_discarded()) value = f.default_value;
    std::string pointer = "/" + f.path;
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    object[nlohmann::ordered_json::json_pointer(pointer)] = std::move(value);
  }
  return object;
}

}  // namespace

nlohmann::ordered_json fields_to_json(const std::vector<FieldInfo>& fields) {
  return element_json(fields);
}

namespace {

std::string elements_json(const std::vector<std::vector<FieldInfo>>& elements) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const std::vector<FieldInfo>& fields : elements) array.push_back(element_json(fields));
  return array.dump();
}

std::string dump_json(const json& value) {
  return value.dump(-1, ' ', /*ensure_ascii=*/true, json::error_handler_t::replace);
}

// Paths cannot index into arrays, so --set ocean.cascades[0].resolution=128 creates a field named
// "cascades[0]" in ocean. For such a key naming a declared array, returns the fix: the whole array (from
// the file, else the defaults) with that element changed, ready to paste. "" for other keys.
std::string index_hint(const std::string& key, const json& value, const json& object,
                       const std::map<std::string, std::string, std::less<>>& array_defaults,
                       const std::string& object_path) {
  const size_t bracket = key.find('[');
  if (bracket == std::string::npos || bracket == 0) return "";
  const std::string name = key.substr(0, bracket);
  const auto defaults = array_defaults.find(name);
  if (defaults == array_defaults.end()) return "";
  const auto in_file = object.find(name);
  json array = in_file != object.end() && in_file->is_array() ? *in_file : json::parse(defaults->second);
  size_t index = 0;
  const char* first = key.data() + bracket + 1;
  const char* last = key.data() + key.size() - 1;  // the closing ']'
  const auto [end, error] = std::from_chars(first, last, index);
  if (key.back() == ']' && error == std::errc() && end == last && index < array.size()) {
    if (array[index].is_object() && value.is_object()) {
      array[index].merge_patch(value);
    } else {
      array[index] = value;
    }
  }
  return "a field path cannot index into an array; set the whole array instead, e.g. --set '" +
         join_path(object_path, name) + "=" + dump_json(array) + "'";
}

}  // namespace

std::string format_number(double v) {
  char buf[32];
  if (std::abs(v) < 1e15 && std::floor(v) == v) {
    std::snprintf(buf, sizeof buf, "%.0f", v);  // whole numbers exactly: seeds, sizes
    return buf;
  }
  // The shortest text that reads back to the same value, so a saved scene reloads bit for bit; a value
  // that came from a float is printed as that float (0.1f prints "0.1", not 0.10000000149011612).
  const float f = static_cast<float>(v);
  const auto [end, error] = static_cast<double>(f) == v ? std::to_chars(buf, buf + sizeof buf, f)
                                                        : std::to_chars(buf, buf + sizeof buf, v);
  return error == std::errc() ? std::string(buf, end) : std::string("0");
}

// ---- Bounds ----

Bounds Bounds::between(double lo, double hi) {
  Bounds b;
  b.min = lo;
  b.max = hi;
  return b;
}

Bounds Bounds::above(double lo) {
  Bounds b;
  b.min = lo;
  b.min_open = true;
  return b;
}

Bounds Bounds::at_least(double lo) {
  Bounds b;
  b.min = lo;
  return b;
}

Bounds Bounds::above_up_to(double lo, double hi) {
  Bounds b = between(lo, hi);
  b.min_open = true;
  return b;
}

bool Bounds::contains(double v) const {
  const bool min_ok = min_open ? v > min : v >= min;
  const bool max_ok = max_open ? v < max : v <= max;
  return min_ok && max_ok;
}

std::string Bounds::describe() const {
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max && !min_open && !max_open) return format_number(min) + " to " + format_number(max);
  std::string out;
  if (has_min) out = (min_open ? "> " : ">= ") + format_number(min);
  if (has_max)
    out += (out.empty() ? "" : " and ") + std::string(max_open ? "< " : "<= ") + format_number(max);
  return out.empty() ? "any" : out;
}

// ---- Diagnostics ----

namespace {
// True if `inner` is `outer` or a field/element below it ("camera.position[1]" is within "camera.position").
bool within(std::string_view inner, std::string_view outer) {
  if (!inner.starts_with(outer)) return false;
  return inner.size() == outer.size() || inner[outer.size()] == '.' || inner[outer.size()] == '[';
}
}  // namespace

void Diagnostics::error(std::string_view path, std::string_view problem, std::string_view fix) {
  std::string line = source_ + ": " + (path.empty() ? std::string("(top level)") : std::string(path)) + ": " +
                     std::string(problem) + "; " + std::string(fix);
  // Either direction: --set camera.fov_deg.x=1 turns camera.fov_deg into an object, reported at fov_deg.
  for (const auto& [override_path, assignment] : overrides_) {
    if (!path.empty() && (within(path, override_path) || within(override_path, path))) {
      line += " (value from --set " + assignment + ")";
      break;
    }
  }
  lines_.push_back(std::move(line));
}

void Diagnostics::file_error(std::string_view problem, std::string_view fix) {
  lines_.push_back(source_ + ": " + std::string(problem) + (fix.empty() ? "" : "; " + std::string(fix)));
}

void Diagnostics::note_override(std::string path, std::string assignment) {
  overrides_.insert(overrides_.begin(), {std::move(path), std::move(assignment)});  // last --set wins
}

Error Diagnostics::to_error() const {
  std::string message;
  for (const std::string& line : lines_) message += (message.empty() ? "" : "\n") + line;
  return Error{message};
}

// ---- ObjectReader ----

ObjectReader::ObjectReader(const nlohmann::json& object, std::string path, Diagnostics& diag)
    : object_(&object), diag_(&diag), path_(std::move(path)) {}

ObjectReader::ObjectReader(std::string path, std::vector<FieldInfo>& catalog)
    : catalog_(&catalog), path_(std::move(path)) {}

std::string ObjectReader::child_path(std::string_view name) const {
  return join_path(path_, name);
}

const json* ObjectReader::lookup(std::string_view name) {
  declared_.emplace_back(name);
  if (describing()) return nullptr;
  const auto it = object_->find(name);
  return it == object_->end() ? nullptr : &*it;
}

void ObjectReader::describe(std::string_view name, std::string type, std::string_view unit,
                            std::string default_value, std::string range, std::string_view doc,
                            Bounds bounds) {
  FieldInfo info;
  info.path = child_path(name);
  info.type = std::move(type);
  info.unit = std::string(unit);
  info.default_value = std::move(default_value);
  info.range = std::move(range);
  info.doc = std::string(doc);
  info.bounds = bounds;
  catalog_->push_back(std::move(info));
}

bool ObjectReader::has(std::string_view name) const {
  return !describing() && object_->find(name) != object_->end();
}

std::optional<double> ObjectReader::read_number(std::string_view name, const std::string& default_text,
                                                Bounds bounds, std::string_view unit, bool as_float) {
  const json* j = lookup(name);
  if (!j) return std::nullopt;
  const std::string path = child_path(name);
  const std::string fix = "allowed: number " + with_unit(bounds.describe(), unit) +
                          (default_text.empty() ? "" : " (default " + default_text + ")");
  const std::optional<double> v = finite_number(*j, path, fix, *diag_);
  if (!v) return std::nullopt;
  // Checked again as float so e.g. 1e-50 for a "> 0" field cannot round to 0.
  if (!bounds.contains(*v) || (as_float && !bounds.contains(static_cast<float>(*v)))) {
    diag_->error(path, describe_value(*j) + " is out of range", fix);
    return std::nullopt;
  }
  return v;
}

void ObjectReader::number(std::string_view name, float& value, Bounds bounds, std::string_view unit,
                          std::string_view doc) {
  if (describing())
    return describe(name, "number", unit, format_number(value), bounds.describe(), doc, bounds);
  if (const std::optional<double> v =
          read_number(name, format_number(value), bounds, unit, /*as_float=*/true))
    value = static_cast<float>(*v);
}

void ObjectReader::number(std::string_view name, std::optional<float>& value, Bounds bounds,
                          std::string_view unit, std::string_view doc) {
  if (describing())
    return describe(name, "number", unit, value ? format_number(*value) : "", bounds.describe(), doc, bounds);
  if (const std::optional<double> v = read_number(name, "", bounds, unit, /*as_float=*/true))
    value = static_cast<float>(*v);
}

void ObjectReader::number(std::string_view name, double& value, Bounds bounds, std::string_view unit,
                          std::string_view doc) {
  if (describing())
    return describe(name, "number", unit, format_number(value), bounds.describe(), doc, bounds);
  if (const std::optional<double> v =
          read_number(name, format_number(value), bounds, unit, /*as_float=*/false))
    value = *v;
}

void ObjectReader::integer(std::string_view name, uint32_t& value, Bounds bounds, std::string_view unit,
                           std::string_view doc) {
  if (describing())
    return describe(name, "integer", unit, std::to_string(value), bounds.describe(), doc, bounds);
  const json* j = lookup(name);
  if (!j) return;
  const std::string path = child_path(name);
  const std::string fix = "allowed: whole number " + with_unit(bounds.describe(), unit) + " (default " +
                          std::to_string(value) + ")";
  const std::optional<double> v = whole_number(*j, path, fix, *diag_);
  if (!v) return;
  if (!bounds.contains(*v) || *v < 0 || *v > std::numeric_limits<uint32_t>::max()) {
    return diag_->error(path, describe_value(*j) + " is out of range", fix);
  }
  value = static_cast<uint32_t>(*v);
}

void ObjectReader::power_of_two(std::string_view name, uint32_t& value, uint32_t min, uint32_t max,
                                std::string_view unit, std::string_view doc) {
  const std::string between = std::to_string(min) + " and " + std::to_string(max);
  if (describing()) {
    describe(name, "integer", unit, std::to_string(value),
             "power of two, " + std::to_string(min) + " to " + std::to_string(max), doc,
             Bounds::between(min, max));
    for (uint64_t p = std::bit_ceil(std::max<uint32_t>(min, 1)); p <= max; p *= 2)
      catalog_->back().choices.push_back(std::to_string(p));
    return;
  }
  const json* j = lookup(name);
  if (!j) return;
  std::string allowed;  // spelled out: "64, 128, 256, 512, 1024" is easier to pick from than a rule
  for (uint64_t p = std::bit_ceil(std::max<uint32_t>(min, 1)); p <= max; p *= 2) {
    allowed += (allowed.empty() ? "" : ", ") + std::to_string(p);
  }
  const std::string path = child_path(name);
  const std::string fix = "allowed: " + with_unit(allowed, unit) + " (default " + std::to_string(value) + ")";
  const std::optional<double> v = whole_number(*j, path, fix, *diag_);
  if (!v) return;
  // Range first: the cast to uint32_t is only defined for values that fit.
  if (*v < min || *v > max || !std::has_single_bit(static_cast<uint32_t>(*v))) {
    return diag_->error(path, describe_value(*j) + " is not a power of two between " + between, fix);
  }
  value = static_cast<uint32_t>(*v);
}

bool ObjectReader::read_floats(std::string_view name, std::span<float> values, std::string_view form,
                               Bounds bounds, std::string_view unit, std::string_view doc) {
  const bool finite_only = !std::isfinite(bounds.min) && !std::isfinite(bounds.max);
  if (describing()) {
    describe(name, std::string(form), unit, format_floats(values),
             finite_only ? "finite" : "each " + bounds.describe(), doc, bounds);
    return false;
  }
  const json* j = lookup(name);
  if (!j) return false;
  const std::string path = child_path(name);
  const std::string count = std::to_string(values.size());
  const std::string fix = "allowed: " + count + (finite_only ? " finite numbers " : " numbers ") +
                          std::string(form) +
                          (finite_only ? (unit.empty() ? "" : " in " + std::string(unit))
                                       : ", each " + with_unit(bounds.describe(), unit)) +
                          " (default " + format_floats(values) + ")";
  if (!j->is_array() || j->size() != values.size()) {
    const std::string got =
        describe_value(*j) + (j->is_array() ? " with " + std::to_string(j->size()) + " elements" : "");
    diag_->error(path, "expected " + std::string(form) + ", got " + got, fix);
    return false;
  }
  for (size_t i = 0; i < values.size(); ++i) {
    const std::string element_path = path + "[" + std::to_string(i) + "]";
    const std::optional<double> v = finite_number((*j)[i], element_path, fix, *diag_);
    if (!v) return false;
    // Checked again as float, as in read_number(), so a value cannot round onto an open bound.
    if (!bounds.contains(*v) || !bounds.contains(static_cast<float>(*v))) {
      diag_->error(element_path, describe_value((*j)[i]) + " is out of range", fix);
      return false;
    }
    values[i] = static_cast<float>(*v);  // callers keep `values` only when all of them were read
  }
  return true;
}

void ObjectReader::vec3(std::string_view name, glm::vec3& value, std::string_view unit,
                        std::string_view doc) {
  vec3(name, value, "[x, y, z]", Bounds::any(), unit, doc);
}

void ObjectReader::vec3(std::string_view name, glm::vec3& value, std::string_view form, Bounds bounds,
                        std::string_view unit, std::string_view doc) {
  float components[3] = {value.x, value.y, value.z};
  if (read_floats(name, components, form, bounds, unit, doc))
    value = {components[0], components[1], components[2]};
}

void ObjectReader::vec2(std::string_view name, glm::vec2& value, std::string_view unit,
                        std::string_view doc) {
  float components[2] = {value.x, value.y};
  if (read_floats(name, components, "[x, z]", Bounds::any(), unit, doc))
    value = {components[0], components[1]};
}

void ObjectReader::flag(std::string_view name, bool& value, std::string_view doc) {
  if (describing()) return describe(name, "boolean", "", value ? "true" : "false", "true, false", doc);
  const json* j = lookup(name);
  if (!j) return;
  if (!j->is_boolean()) {
    return diag_->error(child_path(name), "expected true or false, got " + describe_value(*j),
                        "write true or false without quotes");
  }
  value = j->get<bool>();
}

void ObjectReader::text(std::string_view name, std::string& value, std::string_view doc) {
  if (describing()) return describe(name, "string", "", json(value).dump(), "any", doc);
  const json* j = lookup(name);
  if (!j) return;
  if (!j->is_string()) {
    return diag_->error(child_path(name), "expected a string, got " + describe_value(*j),
                        "write the value in double quotes");
  }
  value = j->get<std::string>();
}

std::optional<ObjectReader> ObjectReader::open_block(std::string_view name, std::string_view doc) {
  if (describing()) {
    describe(name, "object", "", "", "", doc);
    return ObjectReader(child_path(name), *catalog_);
  }
  const json* j = lookup(name);
  if (!j) return std::nullopt;
  if (!j->is_object()) {
    diag_->error(child_path(name), "expected an object {...}, got " + describe_value(*j),
                 "write \"" + std::string(name) +
                     "\": { ... } (see docs/scene-format.md), or leave it out "
                     "to use the defaults");
    return std::nullopt;
  }
  return ObjectReader(*j, child_path(name), *diag_);
}

std::optional<size_t> ObjectReader::choose(std::string_view name, const std::vector<std::string>& names,
                                           size_t current, std::string_view doc) {
  std::string quoted;
  for (const std::string& n : names) quoted += (quoted.empty() ? "" : ", ") + dump_json(n);
  const std::string default_text = current < names.size() ? dump_json(names[current]) : "";
  if (describing()) {
    describe(name, "string", "", default_text, "one of " + quoted, doc);
    catalog_->back().choices = names;
    return std::nullopt;
  }
  const json* j = lookup(name);
  if (!j) return std::nullopt;
  const std::string path = child_path(name);
  const std::string fix =
      "allowed: " + quoted + (default_text.empty() ? "" : " (default " + default_text + ")");
  if (!j->is_string()) {
    diag_->error(path, "expected a string, got " + describe_value(*j), fix);
    return std::nullopt;
  }
  const std::string given = j->get<std::string>();
  const auto it = std::find(names.begin(), names.end(), given);
  if (it != names.end()) return static_cast<size_t>(it - names.begin());
  const std::string suggestion = closest_match(given, names);
  diag_->error(path, describe_value(*j) + " is not one of the allowed names",
               (suggestion.empty() ? "" : "did you mean '" + suggestion + "'? ") + fix);
  return std::nullopt;
}

ObjectReader ObjectReader::describe_array(std::string_view name,
                                          const std::vector<std::vector<FieldInfo>>& defaults,
                                          size_t min_size, size_t max_size, std::string_view doc) {
  describe(name, "array of objects", "", elements_json(defaults),
           std::to_string(min_size) + " to " + std::to_string(max_size) + " elements", doc);
  catalog_->back().min_elements = min_size;
  catalog_->back().max_elements = max_size;
  return ObjectReader(child_path(name) + "[]", *catalog_);
}

std::optional<std::vector<std::optional<ObjectReader>>> ObjectReader::open_array(
    std::string_view name, const std::vector<std::vector<FieldInfo>>& defaults, size_t min_size,
    size_t max_size) {
  const std::string default_json = elements_json(defaults);
  array_defaults_[std::string(name)] = default_json;
  const json* j = lookup(name);
  if (!j) return std::nullopt;
  const std::string path = child_path(name);
  const std::string fix = "allowed: an array of " + std::to_string(min_size) + " to " +
                          std::to_string(max_size) + " objects (default " + default_json + ")";
  if (!j->is_array()) {
    diag_->error(path, "expected an array of objects [{...}, ...], got " + describe_value(*j),
                 fix + ", or leave it out to use the defaults");
    return std::nullopt;
  }
  if (j->size() < min_size || j->size() > max_size) {
    diag_->error(path, "has " + std::to_string(j->size()) + (j->size() == 1 ? " element" : " elements"), fix);
  }
  const std::string example = defaults.empty() ? std::string("{...}") : element_json(defaults.front()).dump();
  std::vector<std::optional<ObjectReader>> elements;
  for (size_t i = 0; i < j->size(); ++i) {
    const std::string element_path = path + "[" + std::to_string(i) + "]";
    if ((*j)[i].is_object()) {
      elements.emplace_back(ObjectReader((*j)[i], element_path, *diag_));
      continue;
    }
    diag_->error(element_path, "expected an object {...}, got " + describe_value((*j)[i]),
                 "each element of " + std::string(name) + " is an object such as " + example);
    elements.emplace_back(std::nullopt);
  }
  return elements;
}

void ObjectReader::rule(std::string_view name, bool holds, std::string_view rule, std::string_view fix) {
  if (describing()) {
    const std::string path = strip_indices(child_path(name));
    for (FieldInfo& info : *catalog_) {
      if (info.path != path || info.range.find(rule) != std::string::npos) continue;  // once per row
      info.range += (info.range.empty() ? "" : ", ") + std::string(rule);
    }
    return;
  }
  if (!holds) diag_->error(child_path(name), "must be " + std::string(rule), fix);
}

void ObjectReader::finish() {
  if (describing()) return;
  std::vector<std::string> allowed = declared_;
  allowed.push_back("comment");
  for (const auto& [key, value] : object_->items()) {
    if (key == "comment") {
      if (!value.is_string()) {
        diag_->error(child_path(key), "expected a string, got " + describe_value(value),
                     "\"comment\" is a free-text note; write it in double quotes");
      }
      continue;
    }
    if (std::find(declared_.begin(), declared_.end(), key) != declared_.end()) continue;
    if (std::string hint = index_hint(key, value, *object_, array_defaults_, path_); !hint.empty()) {
      diag_->error(child_path(key), "unknown field", hint);
      continue;
    }
    const std::string suggestion = closest_match(key, allowed);
    const std::string where = path_.empty() ? "at the top level" : "in " + path_;
    diag_->error(child_path(key), "unknown field",
                 (suggestion.empty() ? "" : "did you mean '" + suggestion + "'? ") + "Fields allowed " +
                     where + ": " + join_list(allowed));
  }
}

// ---- free functions ----

std::optional<json> parse_json_text(std::string_view text, Diagnostics& diag) {
  if (const auto exceeded = io::json_limit_exceeded(text, kSceneJsonLimits)) {
    diag.file_error("JSON: " + *exceeded,
                    "a scene is a few nested objects with short strings and small arrays "
                    "(docs/scene-format.md); check that this is the scene file you meant");
    return std::nullopt;
  }
  // The parser callback sees keys but not paths, so track the path of the container being parsed.
  struct Frame {
    bool is_object;
    std::string path;
    std::set<std::string> keys;
    std::string key;
    size_t index = 0;
  };
  std::vector<Frame> stack;
  auto value_path = [&stack] {
    if (stack.empty()) return std::string();
    const Frame& f = stack.back();
    return f.is_object ? join_path(f.path, f.key) : f.path + "[" + std::to_string(f.index) + "]";
  };
  auto element_done = [&stack] {
    if (!stack.empty() && !stack.back().is_object) ++stack.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        stack.push_back(Frame{event == json::parse_event_t::object_start, value_path(), {}, {}, 0});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!stack.empty()) stack.pop_back();
        element_done();
        break;
      case json::parse_event_t::key:
        if (!stack.empty()) {
          stack.back().key = parsed.get<std::string>();
          if (!stack.back().keys.insert(stack.back().key).second) {
            diag.error(value_path(), "field appears more than once in the same object",
                       "keep only one (JSON parsers would silently use the last one)");
          }
        }
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  };
  try {
    json document = json::parse(text.begin(), text.end(), callback, /*allow_exceptions=*/true,
                                /*ignore_comments=*/false);
    if (!diag.ok()) return std::nullopt;
    return document;
  } catch (const json::parse_error& e) {
    // what() is "[json.exception.parse_error.101] parse error at line L, column C: ..."; keep from "parse".
    std::string what = e.what();
    const size_t start = what.find("] ");
    if (start != std::string::npos) what = what.substr(start + 2);
    diag.file_error("invalid JSON: " + what,
                    "fix the syntax at that position (JSON allows no comments or trailing commas; use a "
                    "\"comment\" field for notes)");
  } catch (const json::exception& e) {  // e.g. out_of_range.406 "number overflow parsing '1e999'"
    std::string what = e.what();
    const size_t start = what.find("] ");
    if (start != std::string::npos) what = what.substr(start + 2);
    diag.file_error("invalid JSON: " + what, "write numbers that fit in a double");
  }
  return std::nullopt;
}

std::string to_markdown_table(const std::vector<FieldInfo>& fields) {
  auto code = [](const std::string& s) { return s.empty() ? std::string() : "`" + s + "`"; };
  std::string out =
      "| Field | Type | Unit | Default | Allowed | Meaning |\n"
      "|---|---|---|---|---|---|\n";
  for (const FieldInfo& f : fields) {
    out += "| " + code(f.path) + " | " + f.type + " | " + f.unit + " | " + code(f.default_value) + " | " +
           f.range + " | " + f.doc + " |\n";
  }
  return out;
}

std::string describe_value(const json& value) {
  // ensure_ascii + replace: never throws on invalid UTF-8, and truncation cannot split a character.
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {  // dump() would print null
    const double v = value.get<double>();
    return std::isnan(v) ? "NaN" : v > 0 ? "infinity" : "-infinity";
  }
  std::string text = value.dump(-1, ' ', /*ensure_ascii=*/true, json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  if (value.is_number() || value.is_null()) return text;
  return std::string(value.type_name()) + " " + text;
}

std::string closest_match(std::string_view name, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const std::string& candidate : candidates) {
    const size_t d = edit_distance(name, candidate);
    // A third of the length (at least 2) catches typos and swaps without suggesting unrelated fields; a
    // shared prefix of 3+ characters catches a missing or extra unit suffix ("fov" vs "fov_deg").
    const size_t shorter = std::min(name.size(), candidate.size());
    const bool prefix =
        shorter >= 3 && edit_distance(name.substr(0, shorter), candidate.substr(0, shorter)) == 0;
    const bool plausible = d <= std::max<size_t>(2, std::max(name.size(), candidate.size()) / 3) || prefix;
    if (plausible && d < best_distance) best_distance = d, best = candidate;
  }
  return best;
}

}  // namespace lagoon::scene
