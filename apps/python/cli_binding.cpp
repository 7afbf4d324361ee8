// lagoon.run, lagoon.export, lagoon.render_sequence and lagoon.verify_dataset: the `lagoon` command's own
// code (run_lagoon.h) run in this process, so the files they write are the CLI's byte for byte and their
// errors are its messages, raised as lagoon.CommandError.
#include <pybind11/stl.h>

#include <stdlib.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.h"
#include "exit_codes.h"
#include "run_lagoon.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "stderr_tee.h"

namespace lagoon::python {
namespace {

namespace fs = std::filesystem;

py::handle command_error;

// A scene given as a lagoon.Scene is written to a temporary file for --scene (paths relative to it), and
// removed afterwards.
class SceneArgument {
 public:
  explicit SceneArgument(const py::object& scene) {
    if (py::isinstance<scene::Scene>(scene)) {
      const scene::Scene& s = scene.cast<const scene::Scene&>();
      char pattern[] = "/tmp/lagoon-scene-XXXXXX";
      if (!::mkdtemp(pattern)) throw std::runtime_error("cannot create a temporary folder for the scene");
      folder_ = pattern;
      path_ = (folder_ / "scene.json").string();
      std::ofstream(path_) << scene::scene_to_json(s, folder_).dump(2) << "\n";
    } else {
      path_ = fspath(scene);
    }
  }
  ~SceneArgument() {
    std::error_code ignored;
    if (!folder_.empty()) fs::remove_all(folder_, ignored);
  }
  const std::string& path() const { return path_; }

 private:
  fs::path folder_;
  std::string path_;
};

std::string number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

void add_overrides(std::vector<std::string>& args, const py::dict& overrides) {
  for (const std::string& assignment : override_strings(overrides))
    args.insert(args.end(), {"--set", assignment});
}

// Runs `args` as `lagoon ARGS` would (stdout and stderr as the command writes them); raises CommandError
// with what it wrote to stderr when it fails, KeyboardInterrupt when Ctrl-C stopped it.
void run_or_raise(const std::vector<std::string>& args) {
  int code = 0;
  std::string messages;
  {
    py::gil_scoped_release unlocked;
    StderrTee tee;
    code = cli::run_lagoon(args);
    std::fflush(stdout);
    messages = tee.finish();
  }
  if (code == cli::kExitOk) return;
  if (code == 128 + SIGINT) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  // The message: what the command wrote to stderr, each line as a terminal shows it (a progress line
  // rewritten with \r counts as its last state), empty lines dropped.
  std::string message;
  std::istringstream lines(messages);
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(line.rfind('\r') == std::string::npos ? 0 : line.rfind('\r') + 1);
    if (!line.empty()) message += (message.empty() ? "" : "\n") + line;
  }
  py::object error = py::reinterpret_borrow<py::object>(command_error)(
      message.empty() ? "lagoon " + args[0] + " failed" : message);
  error.attr("exit_code") = code;
  PyErr_SetObject(command_error.ptr(), error.ptr());
  throw py::error_already_set();
}

int run(const std::vector<std::string>& args) {
  py::gil_scoped_release unlocked;
  const int code = cli::run_lagoon(args);
  std::fflush(stdout);
  std::fflush(stderr);
  return code;
}

py::object export_fields(const py::object& scene, const py::object& out, int frames, std::optional<double> dt,
                         std::optional<double> t0, const py::dict& overrides,
                         const std::optional<std::vector<double>>& surface,
                         std::optional<double> surface_spacing) {
  SceneArgument s(scene);
  const std::string folder = fspath(out);
  std::vector<std::string> args{
      "export", "--scene", s.path(), "--out", folder, "--frames", std::to_string(frames)};
  if (dt) args.insert(args.end(), {"--dt", number(*dt)});
  if (t0) args.insert(args.end(), {"--t0", number(*t0)});
  if (surface) {
    std::string corners;
    for (double v : *surface) corners += (corners.empty() ? "" : ",") + number(v);
    args.insert(args.end(), {"--surface", corners});
  }
  if (surface_spacing) args.insert(args.end(), {"--surface-spacing", number(*surface_spacing)});
  add_overrides(args, overrides);
  run_or_raise(args);
  std::ifstream meta(fs::path(folder) / "meta.json");
  std::stringstream text;
  text << meta.rdbuf();
  return py::module_::import("json").attr("loads")(text.str());
}

std::string render_sequence(const py::object& scene, const py::object& out, int frames,
                            std::optional<double> fps, const py::object& shard,
                            const std::vector<std::string>& aovs, const py::object& path,
                            std::optional<double> time, const py::dict& overrides) {
  SceneArgument s(scene);
  const std::string image = fspath(out);
  std::vector<std::string> args{
      "render", "--scene", s.path(), "--out", image, "--frames", std::to_string(frames)};
  if (fps) args.insert(args.end(), {"--fps", number(*fps)});
  // Always a shard (0/1 when none is given): a sequence, with its manifest, even of one frame.
  std::string shard_text = "0/1";
  if (py::isinstance<py::str>(shard)) {
    shard_text = shard.cast<std::string>();
  } else if (!shard.is_none()) {
    const auto pair = shard.cast<std::pair<long long, long long>>();
    shard_text = std::to_string(pair.first) + "/" + std::to_string(pair.second);
  }
  args.insert(args.end(), {"--shard", shard_text});
  if (!aovs.empty()) {
    std::string list;
    for (const std::string& a : aovs) list += (list.empty() ? "" : ",") + a;
    args.insert(args.end(), {"--aov", list});
  }
  if (!path.is_none()) args.insert(args.end(), {"--path", fspath(path)});
  if (time) args.insert(args.end(), {"--time", number(*time)});
  add_overrides(args, overrides);
  run_or_raise(args);
  // The manifest the shard wrote: OUT.shard-I-of-N.jsonl beside OUT (frames are OUT_0000.png, ...).
  const fs::path p(image);
  const auto slash = shard_text.find('/');
  return (p.parent_path() / (p.stem().string() + ".shard-" + shard_text.substr(0, slash) + "-of-" +
                             shard_text.substr(slash + 1) + ".jsonl"))
      .string();
}

void verify_dataset(const py::object& folder) {
  run_or_raise({"dataset", "verify", fspath(folder)});
}

}  // namespace

void bind_cli(py::module_& m) {
  static py::exception<std::runtime_error> error(m, "CommandError", PyExc_RuntimeError);
  command_error = error;
  m.def("run", &run, py::arg("args"),
        "Runs a `lagoon` command in this process, as the executable would: run(['render', '--scene', "
        "'scenes/default.json', '--out', 'out.png']). Returns its exit code (0 ok, 1 failure, 2 usage, 3 "
        "validation errors); its output goes to this process's stdout and stderr. The GIL is released.");
  m.def("export", &export_fields, py::arg("scene"), py::arg("out"), py::arg("frames") = 1,
        py::arg("dt") = py::none(), py::arg("t0") = py::none(), py::arg("overrides") = py::dict(),
        py::arg("surface") = py::none(), py::arg("surface_spacing") = py::none(),
        "`lagoon export`: the FFT ocean's cascades (displacement, normal, Jacobian, foam), the wakes and the "
        "poses of what moves, for `frames` frames `dt` s apart from `t0`, as .npy files in the folder "
        "`out`; with `surface` = [x0, z0, x1, z1] (m) also the sea over that window of the world, over the "
        "floor (surface_height.npy, `surface_spacing` m apart: --surface). `scene` is a path or a "
        "lagoon.Scene; `overrides` as Scene.load's. Returns meta.json as a "
        "dict; raises CommandError (its exit_code and the CLI's message) when the export fails, leaving no "
        "partial output.");
  m.def("render_sequence", &render_sequence, py::arg("scene"), py::arg("out"), py::arg("frames") = 1,
        py::arg("fps") = py::none(), py::arg("shard") = py::none(),
        py::arg("aovs") = std::vector<std::string>{}, py::arg("path") = py::none(),
        py::arg("time") = py::none(), py::arg("overrides") = py::dict(),
        "`lagoon render --frames`: a dataset sequence. Frame k (at time + k/fps) is written as OUT_kkkk.png "
        "with its metadata JSON and each AOV as .npy beside `out` (e.g. 'set/frame.png'), and listed in the "
        "shard's manifest, whose path is returned. `shard` = (i, n) or 'i/n' renders frames i, i+n, ... (one "
        "shard per process or cluster task); a second call skips the frames already finished. `path`: a "
        "camera path JSON. Raises CommandError with the CLI's message.");
  m.def("verify_dataset", &verify_dataset, py::arg("folder"),
        "`lagoon dataset verify`: every shard's manifest present, every frame finished once, every file of "
        "the size and SHA-256 listed. Raises CommandError with one line per problem (and what to run to "
        "mend it) when the set is not complete and intact.");
}

}  // namespace lagoon::python
