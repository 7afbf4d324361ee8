#include "dataset/ground_truth.h"

#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

#include "dataset/pinhole.h"
#include "shared/ground_truth.h"

namespace lagoon::dataset {

GroundTruth ground_truth(const render::OceanRenderer::SurfaceAov& aov, const scene::Scene& scene,
                         world::CameraSide side, double surface_y) {
  const Pinhole cam = pinhole(scene.camera, aov.width, aov.height);
  const size_t pixels = size_t{aov.width} * aov.height;
  GroundTruth gt{.width = aov.width, .height = aov.height};
  gt.depth.assign(pixels, std::numeric_limits<float>::infinity());
  gt.normal.assign(3 * pixels, 0.0f);
  gt.water_mask.assign(pixels, 0.0f);
  gt.object_id.assign(pixels, 0.0f);
  const double near = scene.camera.near_m;
  for (uint32_t y = 0; y < aov.height; ++y)
    for (uint32_t x = 0; x < aov.width; ++x) {
      const size_t i = size_t{y} * aov.width + x;
      const glm::vec4& world = aov.world_at(x, y);
      const uint32_t what = uint32_t(world.w + 0.5f);
      // Where the pixel's ray starts: in the water when the camera is under it, or, with the lens cutting
      // the surface, when its point on the near plane is below the water there.
      bool from_water = side == world::CameraSide::Below;
      if (side == world::CameraSide::Waterline) {
        const glm::dvec3 d = cam.ray(x, y);
        from_water = (cam.position + d * (near / glm::dot(d, cam.forward()))).y < surface_y;
      }
      gt.water_mask[i] = what == LAGOON_GT_WATER ? 1.0f : from_water ? 2.0f : 0.0f;
      if (what == LAGOON_GT_NONE) continue;
      gt.depth[i] = float(glm::dot(glm::dvec3(world) - cam.position, cam.forward()));
      const glm::vec4& n = aov.normal_at(x, y);
      for (int c = 0; c < 3; ++c) gt.normal[3 * i + c] = n[c];
      gt.object_id[i] = what >= LAGOON_GT_OBJECT0 ? float(what - LAGOON_GT_OBJECT0 + 1)
                        : what == LAGOON_GT_FLOOR ? -1.0f
                                                  : 0.0f;
    }
  return gt;
}

void add_underwater_terms(GroundTruth& gt, const render::OceanRenderer::UnderwaterTerms& terms) {
  const size_t pixels = gt.water_mask.size();
  gt.clean.assign(3 * pixels, std::numeric_limits<float>::quiet_NaN());
  gt.transmission.assign(3 * pixels, 1.0f);
  gt.backscatter.assign(3 * pixels, 0.0f);
  for (size_t i = 0; i < pixels; ++i) {
    if (gt.water_mask[i] != 2.0f) continue;
    const bool hit = terms.clean[i].a > 0.5f;
    for (int c = 0; c < 3; ++c) {
      gt.clean[3 * i + c] = hit ? terms.clean[i][c] : 0.0f;
      gt.transmission[3 * i + c] = hit ? terms.transmission[i][c] : 0.0f;
      gt.backscatter[3 * i + c] = terms.backscatter[i][c];
    }
  }
}

const AovKind* find_aov(std::string_view name) {
  for (const AovKind& a : kAovs)
    if (name == a.name) return &a;
  return nullptr;
}

std::string aov_names(const std::string& separator) {
  std::string out;
  for (const AovKind& a : kAovs) out += (out.empty() ? "" : separator) + a.name;
  return out;
}

const std::vector<float>& GroundTruth::plane(const std::string& name) const {
  if (const AovKind* a = find_aov(name)) return this->*(a->plane);
  throw std::out_of_range("no AOV named '" + name + "'");
}

bool GroundTruth::needs_terms(const std::string& name) {
  const AovKind* a = find_aov(name);
  return a && a->needs_terms;
}

GroundTruth frame_ground_truth(render::OceanRenderer& renderer, const scene::Scene& scene, bool with_terms) {
  const render::OceanRenderer::SurfaceAov aov = renderer.render_surface_aov(scene, /*with_objects=*/true);
  const VkExtent2D extent{scene.render.width, scene.render.height};
  const world::CameraSide side = renderer.camera_side(scene, extent);
  const double surface_y = side == world::CameraSide::Waterline
                               ? renderer.camera_medium().surface_height(
                                     scene.camera.position.x, scene.camera.position.z, scene.time_s)
                               : 0.0;
  GroundTruth gt = ground_truth(aov, scene, side, surface_y);
  if (with_terms) add_underwater_terms(gt, renderer.render_underwater_terms(scene));
  return gt;
}

}  // namespace lagoon::dataset
