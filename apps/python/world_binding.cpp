// lagoon.World: the scene's floating bodies and vehicles stepped on the CPU (no device), as `lagoon probe
// --object` and `lagoon export` step them (world/floating_objects.h), their poses in the same format; a
// controller's helm orders and placements go to the vehicles' tracks (physics/vehicle_track.h), which a
// Renderer built with world= shares, so the frames show the vehicles where the world put them.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "bindings.h"
#include "ocean/initial_spectrum.h"
#include "scene/scene.h"
#include "world/floating_objects.h"
#include "world/moving_pose.h"
#include "world/vehicle_tracks.h"
#include "world_binding.h"

namespace lagoon::python {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double finite(double value, const char* what, double bound) {
  if (!std::isfinite(value) || std::abs(value) > bound)
    throw py::value_error(std::string(what) + " must be a finite number from " +
                          py::str(py::float_(-bound)).cast<std::string>() + " to " +
                          py::str(py::float_(bound)).cast<std::string>());
  return value;
}

py::array_t<double> rows(const std::vector<glm::dvec3>& points) {
  py::array_t<double> out({py::ssize_t(points.size()), py::ssize_t(3)});
  double* d = out.mutable_data();
  for (const glm::dvec3& p : points) *d++ = p.x, *d++ = p.y, *d++ = p.z;
  return out;
}

py::list vec3(glm::dvec3 v) {
  py::list out;
  for (int i = 0; i < 3; ++i) out.append(v[i]);
  return out;
}

}  // namespace

World::World(const scene::Scene& scene) : scene_(scene), targets_(world::moving_targets(scene_)) {
  auto moving = world::FloatingObjects::create(
      scene_, scene_.ocean, ocean::make_cascade_spectra(scene_.ocean), world::vehicle_tracks(scene_));
  if (!moving) raise_scene_error(moving.error().message);
  moving_ = std::move(moving).value();
}

void World::advance(double time_s) {
  if (!std::isfinite(time_s) || time_s < 0 || time_s > 1e6)
    throw py::value_error("time must be a number of seconds from 0 to 1e6");
  check_body_cost(moving_->hull_seconds_to(time_s), time_s, "World.advance(time)");
  py::gil_scoped_release unlocked;
  moving_->advance(time_s);
  time_s_ = time_s;
}

py::list World::poses() const {
  py::list out;
  for (const world::MovingTarget& target : targets_)
    out.append(to_python(world::moving_pose(scene_, *moving_, target, time_s_)));
  return out;
}

std::vector<std::string> World::vehicle_names() const {
  std::vector<std::string> names;
  for (const scene::Vehicle& v : scene_.vehicles) names.push_back(v.name);
  return names;
}

size_t World::vehicle_index(const py::object& vehicle) const {
  if (py::isinstance<py::int_>(vehicle)) {
    const long long i = vehicle.cast<long long>();
    if (i >= 0 && size_t(i) < scene_.vehicles.size()) return size_t(i);
    throw py::index_error("no vehicle " + std::to_string(i) + "; the scene has " +
                          std::to_string(scene_.vehicles.size()) + " (vehicles[])");
  }
  const std::string name = py::str(vehicle);
  for (size_t i = 0; i < scene_.vehicles.size(); ++i)
    if (scene_.vehicles[i].name == name) return i;
  std::string known;
  for (const scene::Vehicle& v : scene_.vehicles) known += (known.empty() ? "" : ", ") + v.name;
  throw py::key_error("no vehicle named '" + name +
                      "'; the scene's vehicles are: " + (known.empty() ? std::string("none") : known));
}

double World::order_time(std::optional<double> time_s) const {
  const double t = time_s.value_or(time_s_);
  if (!std::isfinite(t) || t < time_s_ || t > 1e6)
    throw py::value_error("an order's time must be from the world's time (" + std::to_string(time_s_) +
                          " s) to 1e6 s: the bodies have already lived the past");
  return t;
}

void World::helm(const py::object& vehicle, double speed_mps, double yaw_rate_degps,
                 std::optional<double> time_s) {
  const size_t v = vehicle_index(vehicle);
  physics::HelmOrder order{finite(speed_mps, "speed_mps", 100.0),
                           finite(yaw_rate_degps, "yaw_rate_degps", 360.0) * kDeg};
  moving_->tracks().at(v)->order(order_time(time_s), order);
}

void World::set_pose(const py::object& vehicle, const std::vector<double>& position_xz, double heading_deg,
                     double speed_mps, double yaw_rate_degps, std::optional<double> time_s) {
  const size_t v = vehicle_index(vehicle);
  if (position_xz.size() != 2)
    throw py::value_error(
        "position_xz must be [x, z] in metres (the height is the water's, or the "
        "vehicle's depth_m under it)");
  physics::TrackPoint where;
  where.position = {finite(position_xz[0], "position_xz[0]", 1e6),
                    finite(position_xz[1], "position_xz[1]", 1e6)};
  where.heading = finite(heading_deg, "heading_deg", 3600.0) * kDeg;
  physics::HelmOrder order{finite(speed_mps, "speed_mps", 100.0),
                           finite(yaw_rate_degps, "yaw_rate_degps", 360.0) * kDeg};
  moving_->tracks().at(v)->place(order_time(time_s), where, order);
}

py::dict World::water_under(const std::string& name) const {
  size_t object = scene_.objects.size() + scene_.vehicles.size();
  for (size_t i = 0; i < scene_.objects.size(); ++i)
    if (scene_.objects[i].name == name && moving_->body(i)) object = i;
  for (size_t i = 0; i < scene_.vehicles.size(); ++i)
    if (scene_.vehicles[i].name == name) object = scene_.objects.size() + i;
  const physics::FloatingBody* body = moving_->hull_body(object);
  if (!body) {
    throw py::key_error("'" + name +
                        "' is neither a floating object (objects[].floating) nor a vehicle at the surface: "
                        "nothing of it feels the water's height");
  }
  const std::vector<glm::dvec3> points = body->sample_points_in_world();
  std::vector<glm::dvec2> xz;
  xz.reserve(points.size());
  for (const glm::dvec3& p : points) xz.emplace_back(p.x, p.z);
  const std::vector<double> water = moving_->water_under(object, xz);
  py::array_t<double> heights(py::ssize_t(water.size()));
  std::copy(water.begin(), water.end(), heights.mutable_data());
  const physics::Wrench& wrench = body->last_wrench();
  py::dict out;
  out["points"] = rows(points);
  out["water_height_m"] = heights;
  out["force_n"] = vec3(wrench.force);
  out["torque_nm"] = vec3(wrench.torque);
  out["wetted_area_m2"] = wrench.wetted_area;
  out["centre_of_mass"] = vec3(body->state().position);
  return out;
}

void bind_world(py::module_& m) {
  py::class_<World>(
      m, "World",
      "The scene's floating bodies (objects[].floating) and vehicles, stepped on the CPU as the "
      "renderer and `lagoon probe --object` step them; vehicles can be steered (helm) or placed (set_pose), "
      "and a Renderer(scene, world=w) draws them where this world puts them.")
      .def(py::init<const scene::Scene&>(), py::arg("scene"),
           "Loads the hulls; SceneError when a model or a vehicle's path cannot be used.")
      .def("advance", &World::advance, py::arg("time"),
           "Steps everything to `time` (s; an earlier time replays from 0, orders kept). The GIL is released "
           "meanwhile.")
      .def("poses", &World::poses,
           "A list of dicts, floating objects then vehicles: object or vehicle (its name), time_s, origin, "
           "orientation_wxyz, centre_of_mass, velocity_mps, angular_velocity_radps.")
      .def("helm", &World::helm, py::arg("vehicle"), py::arg("speed_mps"), py::arg("yaw_rate_degps") = 0.0,
           py::arg("time") = py::none(),
           "From `time` (default: the world's time) on, the vehicle (a name or an index into vehicles[]) "
           "runs at speed_mps along its heading, turning at yaw_rate_degps (positive: clockwise seen from "
           "above, to starboard), leaving its path. Its body, wake and sediment follow.")
      .def("set_pose", &World::set_pose, py::arg("vehicle"), py::arg("position_xz"), py::arg("heading_deg"),
           py::arg("speed_mps") = 0.0, py::arg("yaw_rate_degps") = 0.0, py::arg("time") = py::none(),
           "Puts the vehicle at position_xz = [x, z] (m) heading heading_deg (compass: clockwise from north, "
           "-z, toward east, +x) at `time` (default: the world's time), then runs it as helm() does. Its "
           "height stays the water's (surface) or its depth_m (submerged).")
      .def("water_under", &World::water_under, py::arg("name"),
           "The water as the hull of a floating object or surface vehicle felt it at its last physics step: "
           "points (N x 3, world, where its pressure is sampled), water_height_m (N, the sea there plus "
           "the other vehicles' wakes), force_n and torque_nm (the water's wrench about the centre of mass), "
           "wetted_area_m2, centre_of_mass.")
      .def_property_readonly("vehicles", &World::vehicle_names, "The vehicles' names, in scene order.")
      .def_property_readonly("time", &World::time_s, "The time the bodies were last advanced to (s).");
}

}  // namespace lagoon::python
