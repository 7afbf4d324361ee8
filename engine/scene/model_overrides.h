// `--set ocean.model=NAME` on a scene written for another model: the fields the new model needs
// (ocean/model_constraints.h) follow it, as the demo's model selector does, unless an override sets them
// too. A scene file that picks the model itself is checked as written (validate_ocean_params).
#pragma once
#include <nlohmann/json.hpp>

#include <span>
#include <string>
#include <vector>

namespace lagoon::scene {

// Applies the constraints of the model the last "ocean.model=..." of `overrides` picks to `document` (the
// overrides already applied) and returns one note per field it changed, e.g. "--set ocean.model=sines also
// sets ocean.choppiness 0.8 -> 0: eqs. 1-3 move ... (--set ocean.choppiness=V to choose)". Leaves
// everything else, including a malformed document or an unknown model, to validation.
std::vector<std::string> apply_model_constraints(nlohmann::json& document,
                                                 std::span<const std::string> overrides);

}  // namespace lagoon::scene
