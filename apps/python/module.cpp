// PYBIND11_MODULE: the `lagoon` extension's entry point and the module-wide pieces (exceptions, JSON).
#include "bindings.h"

namespace lagoon::python {

py::handle scene_error;

void raise_scene_error(const std::string& message) {
  PyErr_SetString(scene_error.ptr(), message.c_str());
  throw py::error_already_set();
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
