#include "world/camera_medium.h"

#include <cmath>

namespace lagoon::world {
namespace {

// The height's error bound: well inside the 2 cm margin of the waterline band.
constexpr double kToleranceM = 0.01;

}  // namespace

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
  return probe_->height(time_s, x, z).height;
}

}  // namespace lagoon::world
