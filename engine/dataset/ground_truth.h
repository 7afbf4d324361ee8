// A frame's ground truth as the dataset's AOVs (lagoon render --aov; docs/datasets.md), from the ground-truth
// targets (OceanRenderer::render_surface_aov with objects): per pixel, rows from the top,
//   depth         metres along the optical axis to the first surface the ray meets (+inf: the sky);
//   normal        that surface's unit normal in the world frame (3 values; 0 where none);
//   water_mask    0 the ray runs through air, 1 the water surface, 2 the ray runs through the water;
//   object_id     0 nothing or the water, -1 the sea floor, k + 1 the scene's objects[k], then
//                 objects.size() + v + 1 its vehicles[v];
// and, from the underwater view's terms (OceanRenderer::render_underwater_terms), where the ray runs through
// the water (water_mask 2) the image formation model, drawn = clean · transmission + backscatter, in linear
// RGB in the frame's white units before exposure and tone mapping:
//   clean         the light leaving what the ray meets (0 where it meets nothing within reach);
//   transmission  the share of it that reaches the camera (0 where the ray meets nothing);
//   backscatter   the light the water (sediment, light shafts) adds along the ray.
// Elsewhere no water acts on the ray before its first surface: transmission 1, backscatter 0 and clean NaN.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/ocean_renderer.h"
#include "scene/scene.h"
#include "world/camera_medium.h"

namespace lagoon::dataset {

struct GroundTruth {
  uint32_t width = 0, height = 0;
  std::vector<float> depth, normal, water_mask, object_id;  // normal: 3 per pixel
  std::vector<float> clean, transmission, backscatter;      // 3 per pixel; empty until add_underwater_terms
  // The AOV named `name` (one of kAovs; throws std::out_of_range for another).
  const std::vector<float>& plane(const std::string& name) const;
  // Whether `name` needs the image formation terms (frame_ground_truth's with_terms).
  static bool needs_terms(const std::string& name);
};

// The AOVs, in the order the docs list them: the one list the CLI, the Python module, the dataset's
// preview and GroundTruth read.
struct AovKind {
  const char* name;
  uint32_t channels;                       // floats per pixel: 1, or 3 (a vector or linear RGB)
  bool needs_terms;                        // from the underwater view's image formation terms
  std::vector<float> GroundTruth::*plane;  // where GroundTruth keeps it
};
inline constexpr AovKind kAovs[] = {
    {"depth", 1, false, &GroundTruth::depth},
    {"normal", 3, false, &GroundTruth::normal},
    {"water_mask", 1, false, &GroundTruth::water_mask},
    {"object_id", 1, false, &GroundTruth::object_id},
    {"clean", 3, true, &GroundTruth::clean},
    {"transmission", 3, true, &GroundTruth::transmission},
    {"backscatter", 3, true, &GroundTruth::backscatter},
};
// The AOV named `name`, or nullptr.
const AovKind* find_aov(std::string_view name);
// Their names, in that order, between `separator`s: "depth, normal, ..., backscatter".
std::string aov_names(const std::string& separator = ", ");

// `side`: where the camera was judged to be for the frame; `surface_y`: the water's height above the camera
// (used when the lens cuts the surface, to tell per pixel on which side its ray starts).
GroundTruth ground_truth(const render::OceanRenderer::SurfaceAov& aov, const scene::Scene& scene,
                         world::CameraSide side, double surface_y);

// Fills clean, transmission and backscatter from `terms` (the same frame's).
void add_underwater_terms(GroundTruth& gt, const render::OceanRenderer::UnderwaterTerms& terms);

// The ground truth of the frame `renderer` draws for `scene`, with the image formation terms when
// `with_terms` (one more pass): what `lagoon render --aov` writes and the Python module returns.
GroundTruth frame_ground_truth(render::OceanRenderer& renderer, const scene::Scene& scene, bool with_terms);

}  // namespace lagoon::dataset
