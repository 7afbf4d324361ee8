// The scene's vehicles' tracks (physics/vehicle_track.h): each vehicle's path (vehicles[].path), shared by
// everything that follows the vehicle (its body, its wake, the sediment it stirs), so they agree on where it
// is, also once the demo's helm has taken it off its path.
#pragma once
#include <memory>
#include <vector>

#include "physics/vehicle_track.h"
#include "scene/scene.h"

namespace lagoon::world {

// One per scene vehicle, in order.
using VehicleTracks = std::vector<std::shared_ptr<physics::VehicleTrack>>;

physics::WaypointPath vehicle_path(const scene::VehiclePath& path);
// Fresh tracks on the scene's paths.
VehicleTracks vehicle_tracks(const scene::Scene& scene);
// `tracks` when it has one per scene vehicle, else fresh ones.
VehicleTracks tracks_or_fresh(const scene::Scene& scene, VehicleTracks tracks);

}  // namespace lagoon::world
