// The floor the waves feel (issue 37; ocean/shoaling.h), attached to the scene's ocean when the scene is
// read, so the renderer, WaveQuery, probes, bodies and the Python module all transform the waves over the
// same floor: the slope floor as a depth profile along its axis (one row: its contours are straight), a glTF
// floor's triangles rasterised onto a grid over their extent (at most 256 × 256 samples; beyond the mesh the
// sea is ocean.depth_m deep).
#pragma once
#include <memory>

#include "ocean/depth_profile.h"
#include "scene/scene.h"

namespace lagoon::scene {

// The slope floor's depth from `near` (s = 0) to `far`, a sample every 0.25 m (at most
// LAGOON_SHOALING_MAX_SAMPLES); a glTF floor's on its grid; null for no floor, or for a glTF floor that
// cannot be read (the renderer reports that, naming seafloor.file). `sea_depth_m` is ocean.depth_m.
std::shared_ptr<const ocean::DepthProfile> floor_profile(const Seafloor& floor, double sea_depth_m);

// scene.ocean.floor = floor_profile(scene.seafloor, scene.ocean.depth_m).
void attach_floor(Scene& scene);

}  // namespace lagoon::scene
