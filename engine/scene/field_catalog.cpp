// What describe mode produces, turned into the field reference (docs/scene-format.md's table) and into
// JSON (defaults shown as a document). Declared in scene/json_fields.h.
#include <algorithm>

#include "scene/json_fields.h"

namespace lagoon::scene {

// Rebuilds an object's JSON from its describe-mode rows, so defaults (array elements' too) can be shown as
// JSON ({"patch_size_m":1000,"resolution":256}) without a second, hand-written serializer to keep in sync.
nlohmann::ordered_json fields_to_json(const std::vector<FieldInfo>& fields) {
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

}  // namespace lagoon::scene
