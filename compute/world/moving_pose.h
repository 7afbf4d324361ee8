// The pose and velocities of what moves in a scene (a floating object or a vehicle) as JSON: one format for
// `lagoon probe --object`, the "poses" of `lagoon export`'s meta.json and the Python module's World.poses().
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "scene/scene.h"
#include "world/floating_objects.h"

namespace lagoon::world {

// A floating object (objects[index]) or a vehicle (vehicles[index]).
struct MovingTarget {
  bool vehicle = false;
  size_t index = 0;
};

// [x, y, z] as a JSON array (the probes' and poses' vectors).
nlohmann::json json_vec3(glm::dvec3 v);

// Every floating object, then every vehicle, in scene order.
std::vector<MovingTarget> moving_targets(const scene::Scene& scene);

// {"object"|"vehicle": name, "time_s", "origin", "orientation_wxyz", "centre_of_mass", "velocity_mps",
//  "angular_velocity_radps"} at the time `moving` was advanced to.
nlohmann::json moving_pose(const scene::Scene& scene, const FloatingObjects& moving, MovingTarget target,
                           double time_s);

}  // namespace lagoon::world
