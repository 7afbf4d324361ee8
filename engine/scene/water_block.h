// The scene's "water" block: optics::WaterParams (compute/optics/water_params.h).
#pragma once
#include "optics/water_params.h"
#include "scene/json_fields.h"

namespace lagoon::scene {

void read_water(ObjectReader& r, optics::WaterParams& w);

}  // namespace lagoon::scene
