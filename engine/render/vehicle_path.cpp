#include "render/vehicle_path.h"

#include <vector>

namespace lagoon::render {

physics::WaypointPath vehicle_path(const scene::VehiclePath& path) {
  std::vector<glm::dvec2> points;
  for (const glm::vec2& w : path.waypoints) points.emplace_back(w);
  return physics::WaypointPath(std::move(points), path.loop, path.speed_mps, path.start_m);
}

}  // namespace lagoon::render
