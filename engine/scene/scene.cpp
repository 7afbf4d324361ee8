#include "scene/scene.h"
#include "scene/scene_io.h"

#include "core/compass.h"
#include "scene/floor_profile.h"
#include "scene/gltf_camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "ocean/springs.h"
#include "ocean/validate.h"

#include "scene/model_overrides.h"
#include "scene/ocean_block.h"
#include "scene/water_block.h"
#include "scene/world_blocks.h"
#include "shared/limits.h"

namespace lagoon::scene {
namespace {

using nlohmann::json;

// ---- The format: one read function per block; each line declares one field. ----

// Unit view direction for a compass yaw (core/compass.h, like the sun's azimuth) and a pitch above the
// horizon. In double so that pitch -90 gives x and z of ~1e-17, not float cos() noise.
glm::vec3 view_direction(float yaw_deg, float pitch_deg) {
  return glm::vec3(compass::direction_deg(yaw_deg, pitch_deg));
}

void read_camera_gltf(ObjectReader& r, CameraFromGltf& g) {
  r.text("file", g.file,
         "glTF 2.0 file (.gltf or .glb) holding the camera, relative to the scene file's folder.");
  r.text("name", g.name, "The camera's name, or its node's, in that file; \"\" = the file's first camera.");
}

void read_camera(ObjectReader& r, Camera& c) {
  r.vec3("position", c.position, "m", "Eye position (y up; the mean water level is y = 0).");
  r.vec3("look_at", c.look_at, "m", "Point the camera looks at; the view direction is look_at - position.");
  // Angles are an input form only: they become look_at, so the renderer reads the view one way.
  std::optional<float> yaw_deg, pitch_deg;
  r.number("yaw_deg", yaw_deg, Bounds::between(-360, 360), "deg",
           "Instead of look_at: compass direction of the view, clockwise from north (-z) toward east (+x); "
           "90 = east.");
  r.number("pitch_deg", pitch_deg, Bounds::between(-90, 90), "deg",
           "With yaw_deg: angle of the view above the horizon; 0 = level, -90 = straight down.");
  // Presence, not values, decides these rules: a given but out-of-range angle gets its own error only.
  const bool has_yaw = r.has("yaw_deg"), has_pitch = r.has("pitch_deg"), has_look_at = r.has("look_at");
  r.rule("pitch_deg", has_pitch || !has_yaw, "given with yaw_deg",
         "got yaw_deg alone; add pitch_deg (0 = level, negative looks down)");
  r.rule("yaw_deg", has_yaw || !has_pitch, "given with pitch_deg",
         "got pitch_deg alone; add yaw_deg (0 = toward north/-z, 90 = toward east/+x)");
  r.rule("look_at", !has_look_at || (!has_yaw && !has_pitch), "left out when yaw_deg or pitch_deg is given",
         "both aim the camera; keep either look_at or yaw_deg and pitch_deg");
  if (yaw_deg && pitch_deg && !has_look_at) {
    // Far enough along the ray that float rounding of a distant position does not bend the direction.
    const float distance = std::max(1.f, glm::length(c.position));
    c.look_at = c.position + distance * view_direction(*yaw_deg, *pitch_deg);
  }
  r.number("fov_deg", c.fov_deg, Bounds::between(1, 170), "deg", "Vertical field of view.");
  r.number("near_m", c.near_m, Bounds::above(0), "m", "Near clipping distance.");
  r.number("far_m", c.far_m, Bounds::above(0), "m",
           "Far clipping distance; the horizon seen from h metres is about 3570 * sqrt(h) m away.");
  r.rule("far_m", c.far_m > c.near_m, "> near_m",
         "got far_m " + format_number(c.far_m) + " and near_m " + format_number(c.near_m) +
             "; raise far_m or lower near_m");
  r.rule("look_at", c.look_at != c.position, "different from position",
         "the view direction is look_at - position, so move look_at to the point you want to face");
  r.block("gltf", c.gltf, read_camera_gltf,
          "Take the camera from a glTF file: its node's position and orientation (roll included), its "
          "vertical field of view and near and far planes. Replaces every other camera field.");
  if (!c.gltf.file.empty()) {  // a saved scene writes an empty gltf block beside the fields
    for (const char* field : {"position", "look_at", "yaw_deg", "pitch_deg", "fov_deg", "near_m", "far_m"})
      r.rule(
          field, !r.has(field), "left out when gltf is given",
          "the glTF camera sets the view and the lens; keep either camera.gltf or the other camera fields");
  }
}

void read_sun(ObjectReader& r, Sun& s) {
  r.number("elevation_deg", s.elevation_deg, Bounds::between(-90, 90), "deg",
           "Angle above the horizon; negative puts the sun below it.");
  r.number(
      "azimuth_deg", s.azimuth_deg, Bounds::between(0, 360), "deg",
      "Compass direction of the sun, clockwise from north (-z) toward east (+x); 90 = east, 270 = west.");
  r.number("intensity", s.intensity, Bounds::between(0, 100), "",
           "Multiplier on the sun's brightness; 1 is the reference sun, 0 turns it off.");
}

// The floating objects and surface vehicles replay their physics from bodies_start_s to the frame's time
// (issue 36): at most kMaxBodyHullSecondsPerFrame (100 s of the harbour), refused above that with the fix.
void check_bodies_cost(ObjectReader& r, const Scene& s) {
  double hulls = 0;
  for (const Object& o : s.objects) hulls += o.floating.enabled ? 1 : 0;
  for (const Vehicle& v : s.vehicles) hulls += v.depth_m > 0 ? 0 : 1;
  const double seconds = std::max(0.0, double(s.time_s) - double(s.bodies_start_s));
  const double cost = seconds * hulls;
  const bool holds = cost <= kMaxBodyHullSecondsPerFrame;
  const double settle = kMaxBodyHullSecondsPerFrame / std::max(hulls, 1.0);
  r.rule("time_s", holds, "(time_s - bodies_start_s) x floating hulls <= 300 hull-seconds",
         holds
             ? std::string()
             : "the floating objects and surface vehicles are simulated from rest at bodies_start_s = " +
                   format_number(s.bodies_start_s) + " s: " + format_number(seconds) + " s of " +
                   format_number(hulls) + " hulls is " + format_number(std::round(cost)) +
                   " hull-seconds of physics, more than the 300 a frame may take (about 20 s on lavapipe); "
                   "set bodies_start_s to " +
                   format_number(std::ceil(double(s.time_s) - settle)) + " or later (they then settle for " +
                   format_number(std::floor(settle)) + " s before the frame), or choose time_s <= " +
                   format_number(std::floor(double(s.bodies_start_s) + settle)));
}

// New blocks: write read_<block>() above (or, for a large block, in its own file like ocean_block.cpp or
// world_blocks.cpp) and add one r.block() line here.
// The frame's time: one declaration for the file and for check_time_s().
void read_time(ObjectReader& r, float& time_s) {
  r.number("time_s", time_s, Bounds::between(0, 86400), "s",
           "Simulation time of the rendered frame (at most one day: wave phases are 32-bit floats).");
}

void read_scene(ObjectReader& r, Scene& s) {
  r.block("camera", s.camera, read_camera, "Viewpoint and projection.");
  r.block("sun", s.sun, read_sun, "Direction and strength of sunlight.");
  r.block("ocean", s.ocean, read_ocean, "Wind, waves and foam of the simulated sea.");
  r.block("water", s.water, read_water,
          "Optics of the water and the bottom: the colour LUTs (docs/optics.md).");
  r.block("seafloor", s.seafloor, read_seafloor, "The sea floor: none, a procedural sloping bay, or a mesh.");
  r.array("objects", s.objects, 0, 256, read_object,
          "glTF models placed in the world (boats, buoys, rocks), above or below the water.");
  r.array("vehicles", s.vehicles, 0, 16, read_vehicle,
          "Hulls that follow a path (boats at the surface, AUVs at a depth); docs/physics.md, Vehicles.");
  r.block("wakes", s.wakes, read_wakes,
          "The dynamic wave layer the vehicles' hulls make their wakes in (docs/physics.md, Wakes).");
  r.block("sediment", s.sediment, read_sediment,
          "Sediment the vehicles stir up near the floor, drawn as turbidity (docs/physics.md, Sediment).");
  r.array("lights", s.lights, 0, LAGOON_MAX_LIGHTS, read_light,
          "Point lights, in addition to the sun and sky.");
  r.block("underwater", s.underwater, read_underwater,
          "What a camera under the water sees in the water itself (docs/rendering.md, Under the surface).");
  r.block("render", s.render, read_render, "Output image settings and effects.");
  read_time(r, s.time_s);
  r.number("bodies_start_s", s.bodies_start_s, Bounds::between(0, 86400), "s",
           "The floating objects and surface vehicles start at rest where the scene puts them at this time, "
           "and are simulated from it (docs/physics.md); a frame before it shows them there. A frame at "
           "time_s costs (time_s - this) x the hulls of physics: a late frame needs a late start.");
  check_bodies_cost(r, s);
  // Model springs steps its grid from rest to the frame's time, a bounded number of steps at once.
  const double springs_reach = double(ocean::kSpringsMaxCatchUpSteps) * s.ocean.springs.step_s;
  r.rule("time_s", s.ocean.model != ocean::SurfaceModel::Springs || s.time_s < springs_reach,
         "< what model springs reaches from rest in one go",
         "model springs steps its grid from rest; at ocean.springs.step_s = " +
             format_number(s.ocean.springs.step_s) + " s that is below " + format_number(springs_reach) +
             " s; choose an earlier time");
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

// Files named by the scene are relative to the scene, not to the working directory, so a scene folder can
// be moved as a whole. Whether they exist is left to their readers, which name the file they miss.
void resolve_files(Scene& scene, const std::filesystem::path& folder) {
  auto resolve = [&folder](std::string& file) {
    if (!file.empty() && std::filesystem::path(file).is_relative()) file = (folder / file).string();
  };
  resolve(scene.water.table);
  resolve(scene.camera.gltf.file);
  resolve(scene.seafloor.texture);
  resolve(scene.seafloor.file);
  for (Object& object : scene.objects) resolve(object.file);
  for (Vehicle& vehicle : scene.vehicles) resolve(vehicle.file);
}

}  // namespace

Result<Scene> load_scene(const std::filesystem::path& path, std::span<const std::string> overrides,
                         std::vector<std::string>* notes) {
  try {
    Diagnostics diag(path.string());
    const std::optional<std::string> text =
        read_json_file(path, diag, {"scene file", "scenes/default.json", "about 2 KB"});
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
    std::vector<std::string> constraint_notes = apply_model_constraints(*document, overrides);
    if (notes) notes->insert(notes->end(), constraint_notes.begin(), constraint_notes.end());
    Result<Scene> scene = validate(*document, diag);
    if (scene) {
      scene->source = path;
      resolve_files(*scene, path.parent_path());
      attach_floor(*scene);  // the floor the waves feel (ocean/shoaling.h), once its file is resolved
      if (Result<void> camera = apply_gltf_camera(*scene, path.string()); !camera) return camera.error();
    }
    return scene;
  } catch (const std::exception& e) {  // defensive: a bug here must not take the app down
    return Error{path.string() + ": internal error while loading the scene: " + e.what()};
  }
}

Result<Scene> parse_scene(const nlohmann::json& document, const std::string& source_name) {
  try {
    Diagnostics diag(source_name);
    Result<Scene> scene = validate(document, diag);
    if (scene) attach_floor(*scene);
    return scene;
  } catch (const std::exception& e) {
    return Error{source_name + ": internal error while reading the scene: " + e.what()};
  }
}

Result<void> check_time_s(double time_s, const std::string& source_name) {
  const json document{{"time_s", time_s}};
  Diagnostics diag(source_name);
  ObjectReader reader(document, "", diag);
  float checked = 0.f;
  read_time(reader, checked);
  if (!diag.ok()) return diag.to_error();
  return {};
}

std::vector<FieldInfo> scene_fields() {
  const Scene defaults;
  return scene_fields(defaults);
}

std::vector<FieldInfo> scene_fields(const Scene& scene) {
  std::vector<FieldInfo> fields;
  Scene copy = scene;  // describing never writes, but the readers take a mutable reference
  ObjectReader reader("", fields);
  read_scene(reader, copy);
  return fields;
}

}  // namespace lagoon::scene

namespace lagoon::scene {

nlohmann::ordered_json scene_to_json(const Scene& scene, const std::filesystem::path& folder) {
  Scene copy = scene;
  auto relative = [&folder](std::string& file) {
    if (file.empty() || folder.empty()) return;
    std::error_code ec;
    const std::filesystem::path rel = std::filesystem::relative(file, folder, ec);
    if (!ec && !rel.empty() && *rel.begin() != "..") file = rel.generic_string();
  };
  // A glTF camera is saved as the view it gave (position, look_at, lens); its roll is not kept.
  copy.camera.gltf = {};
  relative(copy.water.table);
  relative(copy.seafloor.texture);
  relative(copy.seafloor.file);
  for (Object& object : copy.objects) relative(object.file);
  for (Vehicle& vehicle : copy.vehicles) relative(vehicle.file);
  return fields_to_json(scene_fields(copy));
}

Result<void> save_scene(const Scene& scene, const std::filesystem::path& path) {
  const std::filesystem::path absolute = std::filesystem::absolute(path);
  const std::string text = scene_to_json(scene, absolute.parent_path()).dump(2) + "\n";
  const std::filesystem::path temporary = absolute.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(temporary, ec);
      return Error{path.string() + ": cannot write the scene (check that the folder exists and is writable)"};
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, absolute, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    return Error{path.string() + ": cannot write the scene: " + ec.message()};
  }
  return {};
}

}  // namespace lagoon::scene
