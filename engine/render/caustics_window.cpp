#include "render/caustics_window.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "render/sky_light.h"
#include "shared/caustics.h"

namespace lagoon::render {
namespace {

// Mostly ahead of the camera: the part of the floor a view sees best, with this much behind it.
constexpr float kBehindM = 4.0f;

}  // namespace

double refracted_sun_spread_rad(double sun_y, double ior, double unresolved_mss) {
  const double cos_a = std::clamp(sun_y, 0.0, 1.0), sin_w = std::sqrt(1.0 - cos_a * cos_a) / ior;
  const double cos_w = std::sqrt(1.0 - sin_w * sin_w), squeeze = cos_a / (ior * cos_w);
  const double slopes = (1.0 - squeeze) * std::sqrt(std::max(unresolved_mss, 0.0) / 2.0);
  const double disc = 0.5 * kSunDiscRadiusRad * squeeze;
  return std::sqrt(slopes * slopes + disc * disc);
}

CausticsWindow caustics_window(const scene::Scene& scene, glm::vec3 sun, float ior, float unresolved_mss,
                               uint32_t cells) {
  CausticsWindow w;
  // Nothing to light: open water with no floor and no objects.
  const bool lit = scene.seafloor.type != scene::SeafloorType::None || !scene.objects.empty();
  if (!scene.render.effects.caustics || !lit || sun.y <= 0.01f) return w;
  const float size = CausticsWindow::kSizeM;
  w.cells = std::clamp<uint32_t>(cells, 1, LAGOON_CAUSTICS_CELLS);
  w.cell_m = size / float(w.cells);
  const glm::vec3 eye = scene.camera.position, view = scene.camera.look_at - eye;
  const glm::vec2 flat_view(view.x, view.z);
  const glm::vec2 ahead = glm::length(flat_view) > 1e-3f ? glm::normalize(flat_view) : glm::vec2(0.0f);
  const glm::vec2 centre = glm::vec2(eye.x, eye.z) + ahead * (0.5f * size - kBehindM);
  // On the cell lattice, so the pattern does not swim as the camera moves.
  w.origin = glm::floor((centre - 0.5f * size) / w.cell_m) * w.cell_m;
  // Under a flat surface every ray is the refracted sun: it travels away from the sun by tan θt per metre.
  const float sin_t = std::sqrt(std::max(1.0f - sun.y * sun.y, 0.0f)) / ior;
  const float tan_t = sin_t / std::sqrt(1.0f - sin_t * sin_t);
  const glm::vec2 away = sin_t > 1e-6f ? -glm::normalize(glm::vec2(sun.x, sun.z)) : glm::vec2(0.0f);
  const glm::vec2 deepest_shift = -away * (tan_t * w.depths[LAGOON_CAUSTICS_SLICES - 1]);
  // The margin in metres: LAGOON_CAUSTICS_MARGIN cells of the full map's.
  const float margin = float(LAGOON_CAUSTICS_MARGIN) * size / LAGOON_CAUSTICS_CELLS;
  w.source_origin = w.origin + glm::min(deepest_shift, glm::vec2(0.0f)) - margin;
  const glm::vec2 end = w.origin + size + glm::max(deepest_shift, glm::vec2(0.0f)) + margin;
  w.source_cells = glm::uvec2(glm::ceil((end - w.source_origin) / w.cell_m));
  if (scene.render.effects.caustics_blur) {
    // An angular spread δ moves the ray's landing point at depth z by z δ / cos² θt along the plane of
    // incidence (d(z tan θ)/dθ); across it by z δ / cos θt, less: the blur is the along-plane one both ways.
    const double spread = refracted_sun_spread_rad(sun.y, ior, unresolved_mss);
    const double cos2_t = 1.0 - double(sin_t) * sin_t;
    for (int k = 0; k < LAGOON_CAUSTICS_SLICES; ++k)
      w.blur_cells[k] = float(w.depths[k] * spread / cos2_t / w.cell_m);
  }
  return w;
}

}  // namespace lagoon::render
