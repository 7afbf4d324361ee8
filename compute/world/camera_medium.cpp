#include "world/camera_medium.h"

#include <algorithm>
#include <cmath>

#include "ocean/direct_waves.h"
#include "ocean/random_sea.h"
#include "ocean/shoaling.h"

namespace lagoon::world {
namespace {

// The height's error bound: well inside the 2 cm margin of the waterline band.
constexpr double kToleranceM = 0.01;

}  // namespace

CameraMedium::CameraMedium(const ocean::OceanParams& params, std::vector<ocean::CascadeSpectrum> spectra,
                           double reach_m)
    : params_(params), spectra_(std::move(spectra)), reach_m_(reach_m) {
  const ocean::RandomSea sea = ocean::random_sea(params_, spectra_);
  if (std::optional<ocean::GerstnerParams> summed = ocean::summed_wave_params(params_, sea)) {
    summed_ = std::make_unique<ocean::GerstnerSurface>(*summed);
    floor_ = summed_->shared_shoaling();
    // Their crests reach at most the sum of their largest amplitudes (over the floor, the table's).
    for (size_t i = 0; i < summed_->size(); ++i) {
      double largest = summed->waves[i].amplitude_m;
      if (floor_)
        for (size_t j = 0; j < floor_->samples(); ++j)
          largest = std::max(largest, floor_->table()[(1 + i) * floor_->samples() + j].y);
      reach_m_ += largest;
    }
  } else {
    floor_ = ocean::sea_over_floor(params_, sea);
  }
  // Where its waves shoal, the random sea is higher than in deep water (its scale over 1, layer 0).
  double gain = 1;
  if (floor_)
    for (size_t j = 0; j < floor_->samples(); ++j) gain = std::max(gain, floor_->table()[j].y);
  reach_m_ += (gain - 1) * reach_m;
}

CameraSide CameraMedium::side(const glm::vec3& camera, double lens_m, double time_s) {
  last_queried_ = false;
  if (forced_) return *forced_;
  // The near plane's corners lie up to lens_m away, where the surface may be up to lens_m higher or lower
  // (slopes below 1) than above the camera.
  const double band = lens_m > 0 ? 2.0 * lens_m + 0.02 : 0.0;
  if (camera.y > reach_m_ + band) return CameraSide::Above;
  if (camera.y < -reach_m_ - band) return CameraSide::Below;
  last_queried_ = true;
  const double height = surface_height(camera.x, camera.z, time_s);
  if (std::abs(camera.y - height) < band) return CameraSide::Waterline;
  return camera.y < height ? CameraSide::Below : CameraSide::Above;
}

double CameraMedium::surface_height(double x, double z, double time_s) {
  if (!probe_) probe_ = std::make_unique<ocean::HeightProbe>(params_, spectra_, kToleranceM);
  double height = probe_->height(time_s, x, z, floor_.get()).height;
  if (floor_) height *= floor_->ground({x, z}).y;
  if (summed_) height += summed_->sample(time_s, x, z).height;
  return height;
}

}  // namespace lagoon::world
