// PYBIND11_MODULE: the `lagoon` extension's entry point and the module-wide pieces (exceptions, JSON).
#include "bindings.h"

#include <cstdio>
#include <filesystem>

namespace lagoon::python {

py::handle scene_error;

void raise_scene_error(const std::string& message) {
  PyErr_SetString(scene_error.ptr(), message.c_str());
  throw py::error_already_set();
}

void check_time(const scene::Scene& scene, double time_s, const std::string& what) {
  nlohmann::ordered_json doc = scene::scene_to_json(scene, std::filesystem::current_path());
  doc["time_s"] = time_s;
  if (auto checked = scene::parse_scene(nlohmann::json(doc), what); !checked)
    raise_scene_error(checked.error().message);
}

void check_time_bounds(double time_s, const std::string& what) {
  if (auto checked = scene::check_time_s(time_s, what); !checked) raise_scene_error(checked.error().message);
}

void check_body_cost(double hull_seconds, double time_s, const std::string& what) {
  if (hull_seconds > scene::kMaxBodyHullSecondsPerFrame) {
    char message[512];
    std::snprintf(message, sizeof message,
                  "%s: time_s: the floating objects and surface vehicles would be simulated for %.0f "
                  "hull-seconds to reach %g s, more than the %.0f allowed at once (about 20 s on lavapipe); "
                  "bring them there in steps (each call steps on from the one before), or set the scene's "
                  "bodies_start_s closer to it (docs/physics.md)",
                  what.c_str(), hull_seconds, time_s, scene::kMaxBodyHullSecondsPerFrame);
    raise_scene_error(message);
  }
}

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

std::vector<std::string> override_strings(const py::dict& overrides) {
  std::vector<std::string> out;
  for (const auto& [key, value] : overrides) {
    const std::string path = py::str(key);
    out.push_back(path + "=" +
                  (py::isinstance<py::str>(value) ? value.cast<std::string>() : from_python(value).dump()));
  }
  return out;
}

std::string fspath(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

nlohmann::json from_python(const py::handle& o) {
  return nlohmann::json::parse(py::str(py::module_::import("json").attr("dumps")(o)).cast<std::string>());
}

}  // namespace lagoon::python

PYBIND11_MODULE(lagoon, m) {
  using namespace lagoon::python;
  m.doc() =
      "Lagoon, a physically grounded ocean simulator and renderer: scenes, frames as numpy arrays, and the "
      "water's height, normal and velocity at any point and time (docs/python.md).";
  static py::exception<std::runtime_error> error(m, "SceneError", PyExc_ValueError);
  scene_error = error;
  bind_scene(m);
  bind_renderer(m);
  bind_wave_query(m);
  bind_world(m);
  bind_cli(m);
}
