// ObjectReader: each declared field read and checked (read mode) or listed for the docs (describe mode).
// Messages and Bounds are in json_messages.cpp, parsing in json_parse.cpp, the reference in
// field_catalog.cpp.
#include "scene/json_fields.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>

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
std::string elements_json(const std::vector<std::vector<FieldInfo>>& elements) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const std::vector<FieldInfo>& fields : elements) array.push_back(fields_to_json(fields));
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
  // Checked again as float so e.g. 1e-50 for a "> 0" field cannot round to 0, against the bounds as float
  // too: 0.005 rounds to 0.004999999888f, below the double 0.005 it is documented to accept (issue 36).
  if (!bounds.contains(*v) || (as_float && !bounds.as_float().contains(static_cast<float>(*v)))) {
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

void ObjectReader::number(std::string_view name, std::optional<double>& value, Bounds bounds,
                          std::string_view unit, std::string_view doc) {
  if (describing())
    return describe(name, "number", unit, value ? format_number(*value) : "", bounds.describe(), doc, bounds);
  if (const std::optional<double> v = read_number(name, "", bounds, unit, /*as_float=*/false)) value = *v;
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

void ObjectReader::points2(std::string_view name, std::vector<glm::vec2>& value, size_t min_size,
                           size_t max_size, std::string_view unit, std::string_view doc) {
  std::string defaults;
  for (const glm::vec2& p : value) defaults += (defaults.empty() ? "[" : ", ") + format_floats({&p.x, 2});
  defaults = defaults.empty() ? "[]" : defaults + "]";
  const std::string range = std::to_string(min_size) + " to " + std::to_string(max_size) + " points";
  if (describing()) {
    describe(name, "array of [x, z]", unit, defaults, range, doc);
    catalog_->back().min_elements = min_size;
    catalog_->back().max_elements = max_size;
    return;
  }
  const json* j = lookup(name);
  if (!j) return;
  const std::string path = child_path(name);
  const std::string fix = "allowed: an array of " + range + " [x, z]" +
                          (unit.empty() ? "" : " in " + std::string(unit)) + ", e.g. [[0, 0], [40, 10]]";
  if (!j->is_array() || j->size() < min_size || j->size() > max_size) {
    const std::string got =
        describe_value(*j) + (j->is_array() ? " with " + std::to_string(j->size()) + " elements" : "");
    return diag_->error(path, "expected " + range + " [[x, z], ...], got " + got, fix);
  }
  std::vector<glm::vec2> points;
  for (size_t i = 0; i < j->size(); ++i) {
    const std::string element_path = path + "[" + std::to_string(i) + "]";
    const json& e = (*j)[i];
    if (!e.is_array() || e.size() != 2)
      return diag_->error(element_path, "expected [x, z], got " + describe_value(e), fix);
    glm::vec2 p{};
    for (int c = 0; c < 2; ++c) {
      const std::optional<double> v =
          finite_number(e[c], element_path + "[" + std::to_string(c) + "]", fix, *diag_);
      if (!v) return;
      p[c] = static_cast<float>(*v);
    }
    points.push_back(p);
  }
  value = std::move(points);
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
  const std::string example =
      defaults.empty() ? std::string("{...}") : fields_to_json(defaults.front()).dump();
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

}  // namespace lagoon::scene
