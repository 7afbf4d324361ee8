#include "scene/camera_path.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace lagoon::scene {
namespace {

void read_key(ObjectReader& r, CameraKey& key) {
  r.number("t", key.t, Bounds::at_least(0), "s", "time of this keyframe from the path's start");
  r.vec3("position", key.position, "m", "where the camera is (world frame, y up)");
  r.vec3("look_at", key.look_at, "m", "the point it aims at");
  r.rule("position", r.has("position"), "given (required)", "add \"position\": [x, y, z]");
  r.rule("look_at", r.has("look_at"), "given (required)", "add \"look_at\": [x, y, z]");
  r.rule("look_at", key.look_at != key.position, "different from position",
         "aim the camera at a point away from where it is");
}

void read_camera_path(ObjectReader& r, CameraPath& path) {
  r.array("keyframes", path.keys, 2, 4096, read_key,
          "the flight: keyframes in time order, the first at t = 0; the camera passes through each");
  r.rule("keyframes", r.has("keyframes"), "given (required)", "list at least two keyframes");
  if (path.keys.size() < 2) return;
  r.rule("keyframes[0].t", path.keys[0].t == 0, "0 (a path starts at its first keyframe)",
         "shift the keyframes' times so the first is 0");
  for (size_t i = 1; i < path.keys.size(); ++i) {
    char previous[64];
    std::snprintf(previous, sizeof(previous), "%g", path.keys[i - 1].t);
    r.rule("keyframes[" + std::to_string(i) + "].t", path.keys[i].t > path.keys[i - 1].t,
           "greater than the previous keyframe's t",
           "list keyframes in time order, each later than keyframes[" + std::to_string(i - 1) +
               "] (t = " + previous + ")");
  }
}

// Hermite basis on [t0, t1] with tangents in units per second.
glm::dvec3 hermite(const glm::dvec3& p0, const glm::dvec3& m0, const glm::dvec3& p1, const glm::dvec3& m1,
                   double h, double s) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 +
         (s3 - s2) * h * m1;
}

// Catmull-Rom tangent at key i on uneven times: the chord of its neighbours over their time span.
template <typename Get>
glm::dvec3 tangent(const std::vector<CameraKey>& keys, size_t i, Get get) {
  const size_t a = i == 0 ? 0 : i - 1, b = std::min(i + 1, keys.size() - 1);
  return (glm::dvec3(get(keys[b])) - glm::dvec3(get(keys[a]))) / (keys[b].t - keys[a].t);
}

}  // namespace

Camera CameraPath::at(double t, const Camera& lens) const {
  Camera camera = lens;
  t = std::clamp(t, 0.0, duration_s());
  size_t i = 0;
  while (i + 2 < keys.size() && t > keys[i + 1].t) ++i;
  const double h = keys[i + 1].t - keys[i].t, s = (t - keys[i].t) / h;
  auto curve = [&](auto get) {
    return glm::vec3(hermite(glm::dvec3(get(keys[i])), tangent(keys, i, get), glm::dvec3(get(keys[i + 1])),
                             tangent(keys, i + 1, get), h, s));
  };
  camera.position = curve([](const CameraKey& k) { return k.position; });
  camera.look_at = curve([](const CameraKey& k) { return k.look_at; });
  camera.gltf = {};
  return camera;
}

Result<CameraPath> parse_camera_path(const nlohmann::json& document, const std::string& source_name) {
  Diagnostics diag(source_name);
  if (!document.is_object()) {
    diag.file_error("is not a JSON object", "write {\"keyframes\": [{\"t\": 0, \"position\": [...], ...}]}");
    return diag.to_error();
  }
  CameraPath path;
  path.keys.clear();
  ObjectReader reader(document, "", diag);
  read_camera_path(reader, path);
  reader.finish();
  if (!diag.ok()) return diag.to_error();
  path.source = source_name;
  return path;
}

Result<CameraPath> load_camera_path(const std::filesystem::path& file) {
  try {
    Diagnostics diag(file.string());
    const std::optional<std::string> text =
        read_json_file(file, diag, {"camera path", "scenes/paths/evaluation.json", "about 1 KB"});
    if (!text) return diag.to_error();
    const std::optional<nlohmann::json> document = parse_json_text(*text, diag);
    if (!document) return diag.to_error();
    return parse_camera_path(*document, file.string());
  } catch (const std::exception& e) {  // defensive: a bug here must not take the app down
    return Error{file.string() + ": internal error while reading the camera path: " + e.what()};
  }
}

std::vector<FieldInfo> camera_path_fields() {
  std::vector<FieldInfo> catalog;
  ObjectReader describer("", catalog);
  CameraPath path;
  read_camera_path(describer, path);
  return catalog;
}

}  // namespace lagoon::scene
