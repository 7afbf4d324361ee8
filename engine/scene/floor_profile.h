// The floor the waves feel (issue 37; ocean/shoaling.h): the scene's slope floor as a depth profile along its
// axis, attached to the scene's ocean when it is read, so the renderer, WaveQuery, probes, bodies and
// exports all transform the waves over the same floor. A glTF floor is not sampled yet (docs/ocean.md,
// "Limits"): over it the waves keep ocean.depth_m.
#pragma once
#include <memory>

#include "ocean/depth_profile.h"
#include "scene/scene.h"

namespace lagoon::scene {

// The slope floor's depth from `near` (s = 0) to `far`, a sample every 0.25 m (at most
// LAGOON_SHOALING_MAX_SAMPLES); null for no floor and for a glTF floor.
std::shared_ptr<const ocean::DepthProfile> floor_profile(const Seafloor& floor);

}  // namespace lagoon::scene
