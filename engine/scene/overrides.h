// `--set path=value` overrides: applied to the JSON document before validation, so an override is checked
// exactly like the same value written in the file.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"

namespace lagoon::scene {

struct Assignment {
  std::string path;               // "camera.fov_deg"
  std::vector<std::string> keys;  // {"camera", "fov_deg"}
  nlohmann::json value;           // parsed as JSON if it parses, otherwise the raw text as a string
};

// Splits "a.b.c=value". Errors name the assignment and the expected form "--set path=value".
Result<Assignment> parse_assignment(std::string_view assignment);

// Sets the field named by `assignment` (e.g. "camera.fov_deg=40"), creating missing objects on the way.
// Fails on a malformed assignment or a path that runs through a non-object value.
Result<void> apply_override(nlohmann::json& document, std::string_view assignment);

}  // namespace lagoon::scene
