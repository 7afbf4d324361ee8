// Whether the camera is under the water: its point against the displaced surface right above it, from
// WaveQuery (compute/ocean/wave_query.h) at the frame's time. The query costs an FFT per new time (tens of ms
// on a CPU), so it is asked only when the camera is within the waves' reach of the mean level; further up or
// down the answer is plain.
#pragma once
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "ocean/wave_query.h"

namespace lagoon::render {

class CameraMedium {
 public:
  // `reach_m`: a height the surface does not pass (the renderer's 6σ + 1 m displacement bound).
  CameraMedium(const ocean::OceanParams& params, std::vector<ocean::CascadeSpectrum> spectra, double reach_m)
      : params_(params), spectra_(std::move(spectra)), reach_m_(reach_m) {}

  bool under_water(const glm::vec3& camera, double time_s);
  // How the last answer was found: false when the camera was beyond the waves' reach (no query).
  bool last_queried() const { return last_queried_; }

 private:
  ocean::OceanParams params_;
  std::vector<ocean::CascadeSpectrum> spectra_;
  double reach_m_;
  std::unique_ptr<ocean::WaveQuery> query_;  // created on first need
  bool last_queried_ = false;
};

}  // namespace lagoon::render
