// The scene's "ocean" block: the fields of ocean::OceanParams (compute/ocean/ocean_params.h). Kept out of
// scene.cpp because it is the largest block and the one the physics work will keep growing.
#pragma once
#include "ocean/ocean_params.h"
#include "scene/json_fields.h"

namespace lagoon::scene {

void read_ocean(ObjectReader& r, ocean::OceanParams& o);

}  // namespace lagoon::scene
