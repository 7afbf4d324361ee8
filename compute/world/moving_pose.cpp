#include "world/moving_pose.h"

namespace lagoon::world {
nlohmann::json json_vec3(glm::dvec3 v) {
  return {v.x, v.y, v.z};
}

std::vector<MovingTarget> moving_targets(const scene::Scene& scene) {
  std::vector<MovingTarget> out;
  for (size_t o = 0; o < scene.objects.size(); ++o)
    if (scene.objects[o].floating.enabled) out.push_back({false, o});
  for (size_t v = 0; v < scene.vehicles.size(); ++v) out.push_back({true, v});
  return out;
}

nlohmann::json moving_pose(const scene::Scene& scene, const FloatingObjects& moving, MovingTarget target,
                           double time_s) {
  glm::dvec3 origin, centre, velocity, angular;
  glm::dquat q;
  if (target.vehicle) {
    const physics::VehicleMotion& motion = moving.vehicle(target.index);
    origin = motion.model_origin();
    q = motion.orientation();
    centre = motion.hull() ? motion.hull()->state().position : origin;
    velocity = motion.velocity();
    angular = motion.angular_velocity();
  } else {
    const physics::FloatingBody& body = *moving.body(target.index);
    origin = body.model_origin();
    q = body.state().orientation;
    centre = body.state().position;
    velocity = body.state().velocity;
    angular = body.state().angular_velocity;
  }
  return {{target.vehicle ? "vehicle" : "object",
           target.vehicle ? scene.vehicles[target.index].name : scene.objects[target.index].name},
          {"time_s", time_s},
          {"origin", json_vec3(origin)},
          {"orientation_wxyz", {q.w, q.x, q.y, q.z}},
          {"centre_of_mass", json_vec3(centre)},
          {"velocity_mps", json_vec3(velocity)},
          {"angular_velocity_radps", json_vec3(angular)}};
}

}  // namespace lagoon::world
