#include "scene/scene.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "ocean/validate.h"

#include "scene/ocean_block.h"
#include "scene/water_block.h"

namespace lagoon::scene {
namespace {

using nlohmann::json;

// ---- The format: one read function per block; each line declares one field. ----

void read_camera(ObjectReader& r, Camera& c) {
  r.vec3("position", c.position, "m", "Eye position (y up; the mean water level is y = 0).");
  r.vec3("look_at", c.look_at, "m", "Point the camera looks at; the view direction is look_at - position.");
  r.number("fov_deg", c.fov_deg, Bounds::between(1, 170), "deg", "Vertical field of view.");
  r.number("near_m", c.near_m, Bounds::above(0), "m", "Near clipping distance.");
  r.number("far_m", c.far_m, Bounds::above(0), "m",
           "Far clipping distance; the horizon seen from h metres is about 3570 * sqrt(h) m away.");
  r.rule("far_m", c.far_m > c.near_m, "> near_m",
         "got far_m " + format_number(c.far_m) + " and near_m " + format_number(c.near_m) +
             "; raise far_m or lower near_m");
  r.rule("look_at", c.look_at != c.position, "different from position",
         "the view direction is look_at - position, so move look_at to the point you want to face");
}

void read_sun(ObjectReader& r, Sun& s) {
  r.number("elevation_deg", s.elevation_deg, Bounds::between(-90, 90), "deg",
           "Angle above the horizon; negative puts the sun below it.");
  r.number(
      "azimuth_deg", s.azimuth_deg, Bounds::between(0, 360), "deg",
      "Compass direction of the sun, clockwise from +z (north) toward +x (east); 90 = east, 270 = west.");
  r.number("intensity", s.intensity, Bounds::between(0, 100), "",
           "Multiplier on the sun's brightness; 1 is the reference sun, 0 turns it off.");
}

void read_render(ObjectReader& r, RenderSettings& s) {
  r.integer("width", s.width, Bounds::between(16, 8192), "px", "Output image width.");
  r.integer("height", s.height, Bounds::between(16, 8192), "px", "Output image height.");
  r.number("exposure", s.exposure, Bounds::between(0.01, 100), "",
           "Linear multiplier on scene brightness before display encoding; 2 is one stop brighter.");
  r.number("gamma", s.gamma, Bounds::between(1, 3), "", "Display gamma used to encode the output.");
}

// New blocks: write read_<block>() above (or, for a large block, in its own <block>_block.cpp like
// ocean_block.cpp) and add one r.block() line here.
void read_scene(ObjectReader& r, Scene& s) {
  r.block("camera", s.camera, read_camera, "Viewpoint and projection.");
  r.block("sun", s.sun, read_sun, "Direction and strength of sunlight.");
  r.block("ocean", s.ocean, read_ocean, "Wind, waves and foam of the simulated sea.");
  r.block("water", s.water, read_water,
          "Optics of the water and the bottom: the colour LUTs (docs/optics.md).");
  r.block("render", s.render, read_render, "Output image settings.");
  r.number("time_s", s.time_s, Bounds::between(0, 86400), "s",
           "Simulation time of the rendered frame (at most one day: wave phases are 32-bit floats).");
}

// ---- Loading ----

Result<Scene> validate(const json& document, Diagnostics& diag) {
  if (!document.is_object()) {
    diag.error("", "expected a JSON object {...}, got " + describe_value(document),
               "a scene file is an object such as {\"camera\": {\"fov_deg\": 50}}; {} uses all defaults");
    return diag.to_error();
  }
  Scene scene;
  ObjectReader reader(document, "", diag);
  read_scene(reader, scene);
  reader.finish();
  if (!diag.ok()) return diag.to_error();
  // Rules across fields (cascade bands that must connect) live with the physics; report them the same way.
  if (auto ocean_ok = ocean::validate(scene.ocean); !ocean_ok) {
    std::istringstream lines(ocean_ok.error().message);
    for (std::string line; std::getline(lines, line);)
      if (!line.empty()) diag.file_error(line, "");
    return diag.to_error();
  }
  return scene;
}

std::optional<std::string> read_file(const std::filesystem::path& path, Diagnostics& diag) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    const std::filesystem::path cwd = std::filesystem::current_path(ec);
    diag.file_error("file not found", "check the path (relative paths start from the working directory " +
                                          cwd.string() + "); scenes/default.json is a starting point");
    return std::nullopt;
  }
  if (std::filesystem::is_directory(status)) {
    diag.file_error("is a directory, not a scene file", "pass a .json file such as scenes/default.json");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diag.file_error(std::string("cannot be opened: ") + std::strerror(errno),
                    "check that the file is readable by this user");
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    diag.file_error("could not be read", "check the file and the disk it is on");
    return std::nullopt;
  }
  return text.str();
}

}  // namespace

Result<Scene> load_scene(const std::filesystem::path& path, std::span<const std::string> overrides) {
  try {
    Diagnostics diag(path.string());
    const std::optional<std::string> text = read_file(path, diag);
    if (!text) return diag.to_error();
    std::optional<json> document = parse_json_text(*text, diag);
    if (!document) return diag.to_error();
    for (const std::string& assignment : overrides) {
      const Result<void> applied = apply_override(*document, assignment);
      if (!applied) {
        diag.file_error(applied.error().message, "");
        continue;
      }
      diag.note_override(parse_assignment(assignment)->path, assignment);
    }
    if (!diag.ok()) return diag.to_error();
    Result<Scene> scene = validate(*document, diag);
    if (scene) {
      scene->source = path;
      // Files named by the scene are relative to the scene, not to the working directory.
      if (!scene->water.table.empty() && std::filesystem::path(scene->water.table).is_relative())
        scene->water.table = (path.parent_path() / scene->water.table).string();
    }
    return scene;
  } catch (const std::exception& e) {  // defensive: a bug here must not take the app down
    return Error{path.string() + ": internal error while loading the scene: " + e.what()};
  }
}

Result<Scene> parse_scene(const nlohmann::json& document, const std::string& source_name) {
  try {
    Diagnostics diag(source_name);
    return validate(document, diag);
  } catch (const std::exception& e) {
    return Error{source_name + ": internal error while reading the scene: " + e.what()};
  }
}

std::vector<FieldInfo> scene_fields() {
  std::vector<FieldInfo> fields;
  Scene defaults;
  ObjectReader reader("", fields);
  read_scene(reader, defaults);
  return fields;
}

}  // namespace lagoon::scene
