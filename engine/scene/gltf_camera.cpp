#include "scene/gltf_camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

#include "gltf/gltf_loader.h"

namespace lagoon::scene {
namespace {

std::string names_of(const std::vector<gltf::Camera>& cameras) {
  std::string names;
  for (const gltf::Camera& c : cameras) names += (names.empty() ? "'" : ", '") + c.name + "'";
  return names;
}

}  // namespace

Result<void> apply_gltf_camera(Scene& scene, const std::string& scene_name) {
  const CameraFromGltf& ref = scene.camera.gltf;
  if (ref.file.empty()) return {};
  const std::string field = scene_name + ": camera.gltf";
  Result<gltf::Model> model = gltf::load_gltf(ref.file, {}, gltf::Content::Nodes);
  if (!model) return Error{field + ".file: " + model.error().message};
  if (model->cameras.empty()) {
    return Error{field + ".file: " + ref.file +
                 " has no camera in its default scene; add one in the modelling tool or remove camera.gltf"};
  }
  auto found = std::find_if(model->cameras.begin(), model->cameras.end(), [&](const gltf::Camera& c) {
    return ref.name.empty() || c.name == ref.name || c.node_name == ref.name;
  });
  if (found == model->cameras.end()) {
    return Error{field + ".name: '" + ref.name + "' is not a camera of " + ref.file + "; it has " +
                 names_of(model->cameras)};
  }
  if (!found->perspective) {
    return Error{field + ".name: '" + found->name +
                 "' is an orthographic camera; Lagoon renders perspective "
                 "views only, so pick a perspective camera"};
  }
  const glm::vec3 position(found->world[3]);
  const glm::vec3 back(found->world[2]), up(found->world[1]);
  if (!(glm::length(back) > 1e-6f) || !(glm::length(up) > 1e-6f)) {
    return Error{field + ": the node of camera '" + found->name +
                 "' is scaled to zero; it has no view direction"};
  }
  Camera& c = scene.camera;
  c.position = position;
  // Far enough along the view that float rounding of a distant position does not bend the direction.
  c.look_at = position - glm::normalize(back) * std::max(1.f, glm::length(position));
  c.up = glm::normalize(up);
  c.fov_deg = glm::degrees(found->yfov_rad);
  c.near_m = found->znear;
  if (found->zfar > 0) {
    c.far_m = found->zfar;
  } else {
    c.far_m = std::max(c.far_m, 10 * c.near_m);  // infinite: keep the scene's far plane
  }
  return {};
}

}  // namespace lagoon::scene
