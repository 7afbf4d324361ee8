// A frame's ground truth as the dataset's AOVs (lagoon render --aov; docs/datasets.md), from the ground-truth
// targets (OceanRenderer::render_surface_aov with objects): per pixel, rows from the top,
//   depth       metres along the optical axis to the first surface the view ray meets (+inf: none, the sky);
//   normal      that surface's unit normal in the world frame (3 values; 0 where none);
//   water_mask  0 the pixel sees through air, 1 the water surface, 2 through the water (the underwater
//   volume); object_id   0 nothing or the water, -1 the sea floor, k + 1 the scene's objects[k], then
//               objects.size() + v + 1 its vehicles[v].
#pragma once
#include <cstdint>
#include <vector>

#include "render/camera_medium.h"
#include "render/ocean_renderer.h"
#include "scene/scene.h"

namespace lagoon::render {

struct GroundTruth {
  uint32_t width = 0, height = 0;
  std::vector<float> depth, normal, water_mask, object_id;  // normal: 3 per pixel
  std::vector<float> clean, transmission, backscatter;      // 3 per pixel; empty until add_underwater_terms
};

// `side`: where the camera was judged to be for the frame; `surface_y`: the water's height above the camera
// (used when the lens cuts the surface, to tell per pixel on which side its ray starts).
GroundTruth ground_truth(const OceanRenderer::SurfaceAov& aov, const scene::Scene& scene, CameraSide side,
                         double surface_y);

// Fills clean, transmission and backscatter from `terms` (the same frame's).
void add_underwater_terms(GroundTruth& gt, const OceanRenderer::UnderwaterTerms& terms);

}  // namespace lagoon::render
