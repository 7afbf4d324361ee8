// The Python module `lagoon` (docs/python.md): each part binds the library code the CLI runs, nothing of its
// own.
#pragma once
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>

namespace lagoon::python {

namespace py = pybind11;

// lagoon.SceneError: bad scene files, fields and overrides, with the message the CLI prints.
extern py::handle scene_error;
// Raises lagoon.SceneError with `message` (the CLI's text: file, field, fix).
[[noreturn]] void raise_scene_error(const std::string& message);

// JSON <-> Python (dict, list, str, float, int, bool, None), through Python's own json module.
py::object to_python(const nlohmann::json& j);
nlohmann::json from_python(const py::handle& o);

void bind_scene(py::module_& m);
void bind_renderer(py::module_& m);
void bind_wave_query(py::module_& m);
void bind_world(py::module_& m);
void bind_cli(py::module_& m);

}  // namespace lagoon::python
