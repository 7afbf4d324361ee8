// A scene vehicle's path (vehicles[].path) as the curve it follows (physics/waypoint_path.h): shared by
// everything that follows a vehicle (its body, its wake, the sediment it stirs), so they agree on where it
// is.
#pragma once
#include "physics/waypoint_path.h"
#include "scene/scene.h"

namespace lagoon::render {

physics::WaypointPath vehicle_path(const scene::VehiclePath& path);

}  // namespace lagoon::render
