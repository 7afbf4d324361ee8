// The Python module `lagoon` (docs/python.md): each part binds the library code the CLI runs, nothing of its
// own.
#pragma once
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/scene_io.h"

namespace lagoon::python {

namespace py = pybind11;

// lagoon.SceneError: bad scene files, fields and overrides, with the message the CLI prints.
extern py::handle scene_error;
// Raises lagoon.SceneError with `message` (the CLI's text: file, field, fix).
[[noreturn]] void raise_scene_error(const std::string& message);

// Checks a new time for `scene` as the file's `time_s` is checked (its bounds, the floating bodies' cost:
// docs/physics.md), by reading the scene back with it; raises lagoon.SceneError with the CLI's message,
// naming `what` as the source.
void check_time(const scene::Scene& scene, double time_s, const std::string& what);
// For a renderer's next frame: the field's bounds alone (scene::check_time_s: check_time() less the bodies'
// rule), then `hull_seconds`, the physics the renderer's bodies would take to reach time_s from where they
// are (OceanRenderer::body_hull_seconds_to), at most scene::kMaxBodyHullSecondsPerFrame.
void check_time_bounds(double time_s, const std::string& what);
void check_body_cost(double hull_seconds, double time_s, const std::string& what);

// JSON <-> Python (dict, list, str, float, int, bool, None), through Python's own json module.
py::object to_python(const nlohmann::json& j);
nlohmann::json from_python(const py::handle& o);

// {"ocean.model": "sines", "camera.position": [0, 3, -10]} as --set's "path=value" strings: a string is
// taken as it is (as on the command line), anything else as its JSON.
std::vector<std::string> override_strings(const py::dict& overrides);
// A str or os.PathLike as a path string (os.fspath).
std::string fspath(const py::handle& path);

void bind_scene(py::module_& m);
void bind_renderer(py::module_& m);
void bind_wave_query(py::module_& m);
void bind_world(py::module_& m);
void bind_cli(py::module_& m);

}  // namespace lagoon::python
