// lagoon.World: the scene's floating bodies and vehicles stepped on the CPU (no device), as `lagoon probe
// --object` and `lagoon export` step them (render/floating_objects.h), their poses in the same format.
#include <cmath>
#include <memory>
#include <vector>

#include "bindings.h"
#include "ocean/initial_spectrum.h"
#include "render/floating_objects.h"
#include "render/moving_pose.h"
#include "scene/scene.h"

namespace lagoon::python {
namespace {

class World {
 public:
  explicit World(const scene::Scene& scene) : scene_(scene), targets_(render::moving_targets(scene_)) {
    auto moving =
        render::FloatingObjects::create(scene_, scene_.ocean, ocean::make_cascade_spectra(scene_.ocean));
    if (!moving) {
      raise_scene_error(moving.error().message);
    }
    moving_ = std::move(moving).value();
  }

  // Brings every body and vehicle to `time_s` in the physics' fixed steps (from time 0 again for an earlier
  // time), the wakes they ride included.
  void advance(double time_s) {
    if (!std::isfinite(time_s) || time_s < 0 || time_s > 1e6)
      throw py::value_error("time must be a number of seconds from 0 to 1e6");
    py::gil_scoped_release unlocked;
    moving_->advance(time_s);
    time_s_ = time_s;
  }

  // One dict per floating object, then per vehicle: what `lagoon probe --object NAME` prints for it.
  py::list poses() const {
    py::list out;
    for (const render::MovingTarget& target : targets_)
      out.append(to_python(render::moving_pose(scene_, *moving_, target, time_s_)));
    return out;
  }

  double time_s() const { return time_s_; }

 private:
  scene::Scene scene_;
  std::vector<render::MovingTarget> targets_;
  std::unique_ptr<render::FloatingObjects> moving_;
  double time_s_ = 0;
};

}  // namespace

void bind_world(py::module_& m) {
  py::class_<World>(
      m, "World",
      "The scene's floating bodies (objects[].floating) and vehicles, stepped on the CPU as the "
      "renderer and `lagoon probe --object` step them.")
      .def(py::init<const scene::Scene&>(), py::arg("scene"),
           "Loads the hulls; SceneError when a model or a vehicle's path cannot be used.")
      .def("advance", &World::advance, py::arg("time"),
           "Steps everything to `time` (s; an earlier time replays from 0). The GIL is released meanwhile.")
      .def("poses", &World::poses,
           "A list of dicts, floating objects then vehicles: object or vehicle (its name), time_s, origin, "
           "orientation_wxyz, centre_of_mass, velocity_mps, angular_velocity_radps.")
      .def_property_readonly("time", &World::time_s, "The time the bodies were last advanced to (s).");
}

}  // namespace lagoon::python
