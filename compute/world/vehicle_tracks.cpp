#include "world/vehicle_tracks.h"

namespace lagoon::world {

physics::WaypointPath vehicle_path(const scene::VehiclePath& path) {
  std::vector<glm::dvec2> points;
  for (const glm::vec2& w : path.waypoints) points.emplace_back(w);
  return physics::WaypointPath(std::move(points), path.loop, path.speed_mps, path.start_m);
}

VehicleTracks vehicle_tracks(const scene::Scene& scene) {
  VehicleTracks tracks;
  for (const scene::Vehicle& v : scene.vehicles)
    tracks.push_back(std::make_shared<physics::VehicleTrack>(vehicle_path(v.path)));
  return tracks;
}

VehicleTracks tracks_or_fresh(const scene::Scene& scene, VehicleTracks tracks) {
  return tracks.size() == scene.vehicles.size() ? std::move(tracks) : vehicle_tracks(scene);
}

}  // namespace lagoon::world
