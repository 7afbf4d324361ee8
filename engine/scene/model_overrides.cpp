#include "scene/model_overrides.h"

#include <algorithm>
#include <optional>

#include "ocean/model_constraints.h"
#include "scene/json_fields.h"
#include "scene/overrides.h"

namespace lagoon::scene {

std::vector<std::string> apply_model_constraints(nlohmann::json& document,
                                                 std::span<const std::string> overrides) {
  std::optional<std::string> model_name;
  std::vector<std::string> set_paths;
  for (const std::string& o : overrides) {
    Result<Assignment> a = parse_assignment(o);
    if (!a) continue;
    set_paths.push_back(a->path);
    if (a->path == "ocean.model" && a->value.is_string()) model_name = a->value.get<std::string>();
  }
  ocean::SurfaceModel model;
  if (!model_name || !ocean::from_string(*model_name, model)) return {};
  if (!document.is_object() || !document.contains("ocean") || !document["ocean"].is_object()) return {};
  nlohmann::json& ocean = document["ocean"];
  const ocean::OceanParams defaults;
  std::vector<std::string> notes;
  for (const ocean::ModelConstraint& c : ocean::model_constraints(model)) {
    const std::string path = std::string("ocean.") + c.field;
    if (std::find(set_paths.begin(), set_paths.end(), path) != set_paths.end()) continue;  // the user's
    const nlohmann::json* given = ocean.contains(c.field) ? &ocean[c.field] : nullptr;
    if (given && !given->is_number()) continue;  // validation names the wrong type
    const double now = given ? given->get<double>() : defaults.*c.member;
    if (now == c.value) continue;
    ocean[c.field] = c.value;
    notes.push_back("--set ocean.model=" + *model_name + " also sets " + path + " " + format_number(now) +
                    " -> " + format_number(c.value) + ": " + c.reason + " (--set " + path + "=V to choose)");
  }
  return notes;
}

}  // namespace lagoon::scene
