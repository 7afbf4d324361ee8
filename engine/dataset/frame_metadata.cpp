#include "dataset/frame_metadata.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include "dataset/pinhole.h"
#include "render/camera.h"

namespace lagoon::dataset {
namespace {

using nlohmann::ordered_json;

ordered_json vec(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

// 4 x 4, row-major, [R t; 0 0 0 1] with R's columns the camera's optical axes.
ordered_json pose(const glm::dmat3& r, const glm::dvec3& t) {
  ordered_json rows = ordered_json::array();
  for (int i = 0; i < 3; ++i) rows.push_back({r[0][i], r[1][i], r[2][i], t[i]});
  rows.push_back({0.0, 0.0, 0.0, 1.0});
  return rows;
}

glm::dmat3 enu_from_world() {
  glm::dmat3 m;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = kEnuFromWorld[row][col];
  return m;
}

// A change of axes (entries 0 and ±1), row-major, as whole numbers.
ordered_json axes(const glm::dmat3& m) {
  ordered_json rows = ordered_json::array();
  for (int i = 0; i < 3; ++i) rows.push_back({int(m[0][i]), int(m[1][i]), int(m[2][i])});
  return rows;
}

}  // namespace

ordered_json frame_metadata(const scene::Scene& scene, long long frame, const FrameFiles& files) {
  const Pinhole cam = pinhole(scene.camera, scene.render.width, scene.render.height);
  const glm::dmat3& world_from_optical = cam.world_from_camera;
  const glm::dvec3& position = cam.position;
  const double fy = cam.fy;
  const glm::dmat3 enu = enu_from_world();
  const glm::dmat3 ned_from_enu(glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1));
  const glm::dvec3 sun(render::sun_direction(scene.sun));

  ordered_json aovs = ordered_json::object();
  for (size_t i = 0; i < files.aovs.size(); ++i) aovs[files.aovs[i]] = files.aov_files[i];
  return {
      {"frame", frame},
      {"time_s", scene.time_s},
      {"image", files.image},
      {"aov", aovs},
      {"width", scene.render.width},
      {"height", scene.render.height},
      {"camera",
       {{"model", "pinhole (OpenCV), no distortion; pixel centres at integer coordinates"},
        {"K", {{cam.fx, 0.0, cam.cx}, {0.0, fy, cam.cy}, {0.0, 0.0, 1.0}}},
        {"distortion", {0.0, 0.0, 0.0, 0.0, 0.0}},
        {"fov_y_deg", scene.camera.fov_deg},
        {"near_m", scene.camera.near_m},
        {"far_m", scene.camera.far_m},
        {"position", vec(position)},
        {"look_at", vec(glm::dvec3(scene.camera.look_at))},
        {"world_from_camera", pose(world_from_optical, position)},
        {"enu_from_camera", pose(enu * world_from_optical, enu * position)},
        {"ned_from_camera", pose(ned_from_enu * enu * world_from_optical, ned_from_enu * enu * position)}}},
      {"frames",
       {{"world", "Lagoon world: right-handed, metres, y up, mean sea level at y = 0; x east, -z north"},
        {"camera", "optical (OpenCV, ROS *_optical_frame): x right, y down, z forward along the view"},
        {"enu_from_world", axes(enu)},
        {"ned_from_enu", axes(ned_from_enu)}}},
      {"sun",
       {{"elevation_deg", scene.sun.elevation_deg},
        {"azimuth_deg", scene.sun.azimuth_deg},
        {"intensity", scene.sun.intensity},
        {"direction_world", vec(sun)},
        {"direction_enu", vec(enu * sun)}}},
      {"water", {{"type", scene.water.type}, {"table", scene.water.table}}},
      {"seed", {{"ocean", scene.ocean.seed}, {"particles", scene.underwater.particles.seed}}},
      {"scene", scene.source.filename().string()},
  };
}

}  // namespace lagoon::dataset
