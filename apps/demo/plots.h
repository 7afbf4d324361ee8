// The panel's pictures: the spectrum S(ω) and the directional spreading of the scene's sea, the colour
// LUTs T0/T1 of its water, per-pass GPU times and the frame-time history.
#pragma once
#include <deque>
#include <vector>

#include "ocean/ocean_params.h"
#include "optics/lut.h"
#include "vk/gpu_timer.h"

namespace lagoon::demo {

void spectrum_plots(const ocean::OceanParams& params);
// Images of the LUTs (display-scaled: each image divided by its brightest texel, gamma 2.2).
void lut_images(const optics::WaterLut& lut);
void pass_time_bars(const std::vector<vk::PassTime>& timings);
void frame_time_graph(const std::deque<float>& frame_ms);

}  // namespace lagoon::demo
