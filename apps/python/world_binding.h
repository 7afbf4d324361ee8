// lagoon.World's class, declared for the Renderer's world= argument (it shares the world's vehicle tracks).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "scene/scene.h"
#include "world/floating_objects.h"
#include "world/moving_pose.h"

namespace lagoon::python {

class World {
 public:
  explicit World(const scene::Scene& scene);

  // Brings every body and vehicle to `time_s` in the physics' fixed steps (from bodies_start_s again for an
  // earlier time), the wakes they ride included.
  void advance(double time_s);
  // One dict per floating object, then per vehicle: what `lagoon probe --object NAME` prints for it.
  py::list poses() const;
  void helm(const py::object& vehicle, double speed_mps, double yaw_rate_degps, std::optional<double> time_s);
  void set_pose(const py::object& vehicle, const std::vector<double>& position_xz, double heading_deg,
                double speed_mps, double yaw_rate_degps, std::optional<double> time_s);
  py::dict water_under(const std::string& name) const;
  std::vector<std::string> vehicle_names() const;

  double time_s() const { return time_s_; }
  const scene::Scene& scene() const { return scene_; }
  const world::VehicleTracks& tracks() const { return moving_->tracks(); }

 private:
  size_t vehicle_index(const py::object& vehicle) const;
  double order_time(std::optional<double> time_s) const;

  scene::Scene scene_;
  std::vector<world::MovingTarget> targets_;
  std::unique_ptr<world::FloatingObjects> moving_;
  double time_s_ = 0;
};

}  // namespace lagoon::python
