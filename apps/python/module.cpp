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
