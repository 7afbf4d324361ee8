// The scene's sea floor on the CPU, as the height function bodies rest on (physics/floor_contact.h): the
// slope floor's closed form, a glTF floor's triangles by ray cast (physics/mesh_floor.h), or with no floor
// drawn ("none") the sea's bottom at ocean.depth_m, the depth its waves are computed for.
#pragma once
#include "core/result.h"
#include "physics/floor_contact.h"
#include "scene/scene.h"

namespace lagoon::world {

// Fails naming seafloor.file when a glTF floor cannot be read.
Result<physics::FloorHeight> floor_height(const scene::Scene& scene);

}  // namespace lagoon::world
