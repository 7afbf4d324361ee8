// A scripted camera flight (lagoon render --path, lagoon bench effects --path; docs/datasets.md): keyframes
// of time, position and aim, read from JSON as strictly as a scene, and interpolated by a C1 cubic
// (Catmull-Rom tangents on the keyframes' own times, so uneven spacing does not overshoot in time): it passes
// through every keyframe, its velocity is continuous, and a flight at constant velocity stays exactly that.
#pragma once
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json_fwd.hpp>

#include "core/result.h"
#include "scene/json_fields.h"
#include "scene/scene.h"

namespace lagoon::scene {

struct CameraKey {
  double t = 0;                         // seconds from the path's start
  glm::vec3 position{0.f, 6.f, -40.f};  // metres, world frame (y up)
  glm::vec3 look_at{0.f, 0.f, 0.f};     // the point the camera aims at
};

struct CameraPath {
  std::filesystem::path source;
  std::vector<CameraKey> keys;  // at least two, t from 0 strictly increasing

  double duration_s() const { return keys.empty() ? 0.0 : keys.back().t; }
  // The camera at path time t (clamped to the path), with the scene camera's lens and up direction.
  Camera at(double t, const Camera& lens) const;
};

// Validates; every problem is one line naming the file and the field ("keyframes[2].t").
Result<CameraPath> load_camera_path(const std::filesystem::path& path);
Result<CameraPath> parse_camera_path(const nlohmann::json& document, const std::string& source_name);
// The field reference (docs/datasets.md), from the same declarations the reader validates with.
std::vector<FieldInfo> camera_path_fields();

}  // namespace lagoon::scene
