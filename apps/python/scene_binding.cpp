// lagoon.Scene: load (with overrides), to_dict, from_dict: scene/scene.h's load_scene, scene_to_json and
// parse_scene, so a scene is read, checked and refused exactly as `lagoon render --scene --set` does.
#include <pybind11/stl.h>

#include <filesystem>
#include <string>
#include <vector>

#include "bindings.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

namespace lagoon::python {

void bind_scene(py::module_& m) {
  py::class_<scene::Scene>(m, "Scene", "A validated scene (docs/scene-format.md).")
      .def_static(
          "load",
          [](const std::string& path, const py::dict& overrides) {
            std::vector<std::string> notes;
            auto scene = scene::load_scene(path, override_strings(overrides), &notes);
            if (!scene) raise_scene_error(scene.error().message);
            for (const std::string& note : notes)
              PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1);  // what a model's override also changed
            return *scene;
          },
          py::arg("path"), py::arg("overrides") = py::dict(),
          "Reads and checks a scene file; `overrides` maps field paths to values as --set does. Raises "
          "SceneError with the file, the field and the fix.")
      .def_static(
          "from_dict",
          [](const py::dict& d, const std::string& source) {
            auto scene = scene::parse_scene(from_python(d), source);
            if (!scene) raise_scene_error(scene.error().message);
            return *scene;
          },
          py::arg("d"), py::arg("source") = "<dict>",
          "A scene from a dict of the file's shape (relative paths from the working folder); `source` "
          "names it in error messages.")
      .def(
          "to_dict",
          [](const scene::Scene& s) { return to_python(scene_to_json(s, std::filesystem::current_path())); },
          "The scene as a dict that from_dict() reads back to the same scene.")
      .def_property(
          "time_s", [](const scene::Scene& s) { return s.time_s; },
          [](scene::Scene& s, double t) {
            check_time(s, t, "Scene.time_s");
            s.time_s = float(t);
          },
          "The simulation time of the frame (s), checked as the file's time_s is.")
      .def_property_readonly("width", [](const scene::Scene& s) { return s.render.width; })
      .def_property_readonly("height", [](const scene::Scene& s) { return s.render.height; })
      .def_property_readonly("source", [](const scene::Scene& s) { return s.source.string(); })
      .def("__repr__", [](const scene::Scene& s) {
        return "<lagoon.Scene " + (s.source.empty() ? std::string("<dict>") : s.source.string()) + ", " +
               std::to_string(s.render.width) + "x" + std::to_string(s.render.height) + ">";
      });
}

}  // namespace lagoon::python
