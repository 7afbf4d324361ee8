// `lagoon lut`'s underwater tables (optics/underwater.h): the .npy files, a preview and their description
// for lut.json, written into the same staged folder as T0/T1.
#pragma once
#include <nlohmann/json.hpp>

#include "core/result.h"
#include "io/staged_output.h"
#include "optics/lut.h"

namespace lagoon::cli {

// Writes underwater_target.npy, underwater_water_down.npy, underwater_water_up.npy and underwater.png;
// returns the "underwater" object for lut.json.
Result<nlohmann::json> write_underwater_tables(const optics::LutInputs& inputs,
                                               const io::StagedOutput& staged);

}  // namespace lagoon::cli
