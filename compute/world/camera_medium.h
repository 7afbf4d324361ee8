// Where the camera is: above the water, under it, or with its lens cutting the surface (the near plane
// crosses the waterline, so the image splits along it). Judged against the displaced surface right above the
// camera at the frame's time, from HeightProbe (compute/ocean/height_probe.h: within 1 cm of the sum the GPU
// draws, 1-2 ms on a CPU). It is asked only when the camera is within the waves' reach of the mean level;
// further up or down the answer is plain.
#pragma once
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <vector>

#include "ocean/gerstner.h"
#include "ocean/height_probe.h"
#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"

namespace lagoon::world {

enum class CameraSide { Above, Below, Waterline };

class CameraMedium {
 public:
  // `reach_m`: a height the surface does not pass (the renderer's 6σ + 1 m displacement bound).
  // The waves summed where they are drawn (model gerstner's and sines', and swell over the cascades) and the
  // floor's transformation (ocean/shoaling.h) are added to the cascades' sea, and to `reach_m`.
  CameraMedium(const ocean::OceanParams& params, std::vector<ocean::CascadeSpectrum> spectra, double reach_m);

  // `lens_m`: how far the near plane reaches from the camera's point (half its diagonal). Within that of
  // the surface, allowing for the surface's slope across it, the frame is drawn on both sides of the
  // waterline.
  CameraSide side(const glm::vec3& camera, double lens_m, double time_s);
  bool under_water(const glm::vec3& camera, double time_s) {
    return side(camera, 0.0, time_s) == CameraSide::Below;
  }
  // The displaced surface's height (m) at (x, z) and time t, within 1 cm (HeightProbe).
  double surface_height(double x, double z, double time_s);
  // How the last answer was found: false when the camera was beyond the waves' reach (no query).
  bool last_queried() const { return last_queried_; }

  // For tests and tools: answer `side` whatever the camera (nullopt: judge again).
  void force(std::optional<CameraSide> side) { forced_ = side; }

 private:
  ocean::OceanParams params_;
  std::vector<ocean::CascadeSpectrum> spectra_;
  double reach_m_;
  std::unique_ptr<ocean::HeightProbe> probe_;  // made on first need (sorting the modes takes ~50 ms)
  // The waves summed where they are drawn, over the floor, and the table that scales the cascades' sea there;
  // the sea's height is the probe's (its own inversion) times that scale, plus the sums (theirs).
  std::unique_ptr<ocean::GerstnerSurface> summed_;
  std::shared_ptr<const ocean::Shoaling> floor_;
  bool last_queried_ = false;
  std::optional<CameraSide> forced_;
};

}  // namespace lagoon::world
