// The water at points, as `lagoon probe` prints it and the Python module returns it: WaveQuery's sea
// (ocean/wave_query.h) plus the vehicles' wakes at that time (world/wake_heights.h), their height added,
// their slopes in the normal and their rate in the vertical velocity (the layer moves the surface only
// vertically).
#pragma once
#include <glm/vec2.hpp>
#include <span>
#include <vector>

#include "core/result.h"
#include "ocean/wave_query.h"
#include "scene/scene.h"

namespace lagoon::world {

struct WaterAtPoints {
  std::vector<ocean::WaveSample> samples;  // the sea with the wakes
  std::vector<double> wake_heights;        // the wakes' part of each height (0 without wakes)
};

// `query` answers for scene.ocean. The wakes run from wakes.history_s before `time_s` around the points'
// centre, as a frame at that time computes them; none when the scene makes none or wakes.felt_by_bodies is
// false. Fails only when the scene's vehicles cannot be set up (the message names the field).
Result<WaterAtPoints> water_at_points(const scene::Scene& scene, ocean::WaveQuery& query, double time_s,
                                      std::span<const glm::dvec2> points);

}  // namespace lagoon::world
